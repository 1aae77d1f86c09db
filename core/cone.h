#pragma once
// NFF open cones and cylinders (`c`): the surface between a base circle and an apex circle,
// no caps. Radius varies linearly along the axis; a cylinder has equal radii.
#include <cstdint>

#include "core/math.h"

namespace rayo {

struct Cone {
    Vec3 base{0.0f};
    float base_radius = 1.0f;
    Vec3 apex{0.0f, 1.0f, 0.0f};
    float apex_radius = 1.0f;
    uint32_t material = 0;
};

// Nearest hit in (tnear, tfar) of a ray (unit direction) with the open cone; the outward normal
// at the hit goes to `normal`. Solves |w⊥ + t·d⊥|² = (r(s))², s the axial coordinate, in double.
bool intersect_cone(const Cone& cone, const Vec3& origin, const Vec3& direction, float tnear,
                    float tfar, float& t_out, Vec3& normal);

}  // namespace rayo
