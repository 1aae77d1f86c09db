#pragma once
// The words a light describes itself with (`describe(out)`, docs/architecture.md "Adding a
// light"): the light lines of `rayo info`, of --stats and of the Python module's Scene.lights,
// as "x y z" triples and "color r g b intensity i".
#include <ostream>

#include "core/math.h"

namespace rayo {

inline void write_triple(std::ostream& out, const Vec3& v) {
    out << v.x << " " << v.y << " " << v.z;
}

inline void write_color_and_intensity(std::ostream& out, const Vec3& color, float intensity) {
    out << " color ";
    write_triple(out, color);
    out << " intensity " << intensity;
}

}  // namespace rayo
