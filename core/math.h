#pragma once
// Vector types used throughout rayo. Float in the hot path (Embree is float); the double types
// are for reference implementations and tests (docs/architecture.md, "Hot-path rules").
#include <glm/glm.hpp>

namespace rayo {

using Vec3 = glm::vec3;
using DVec3 = glm::dvec3;

constexpr float kPi = 3.14159265358979323846f;

inline float max_abs_component(const Vec3& v) {
    return glm::max(glm::abs(v.x), glm::max(glm::abs(v.y), glm::abs(v.z)));
}

// v / |v| for any finite non-zero v: scaled by its largest component first, so that |v|² can
// neither overflow (a triangle's cross product at 3e9 from the origin is ~1e19, its square past
// float range: glm::normalize gave 0 and the lights went dark) nor underflow. Zero for zero.
inline Vec3 unit_vector(const Vec3& v) {
    const float largest = max_abs_component(v);
    if (!(largest > 0.0f)) return Vec3(0.0f);
    return glm::normalize(v / largest);
}

}  // namespace rayo
