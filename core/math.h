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

}  // namespace rayo
