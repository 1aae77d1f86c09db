#pragma once
// A ray R(t) = origin + t·direction, t in (tnear, tfar) (seed 000 eqs. [1]-[2]); direction is
// unit length everywhere in rayo.
#include <limits>

#include "core/math.h"

namespace rayo {

struct Ray {
    Vec3 origin{0.0f};
    Vec3 direction{0.0f, 0.0f, 1.0f};
    float tnear = 0.0f;
    float tfar = std::numeric_limits<float>::infinity();

    Vec3 at(float t) const { return origin + t * direction; }
};

}  // namespace rayo
