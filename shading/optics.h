#pragma once
// Perfect specular reflection and Snell refraction (seed 001). All vectors unit length;
// `incident` points toward the surface, `normal` faces the incident side (N·I < 0).
#include <cmath>
#include <optional>

#include "core/math.h"

namespace rayo {

// seed 001: R = I − 2(I·N)N.
inline Vec3 reflect(const Vec3& incident, const Vec3& normal) {
    return incident - 2.0f * glm::dot(incident, normal) * normal;
}

// seed 001: T = I/n21 + ((−I·N)/n21 − √(1 + ((−I·N)² − 1)/n21²))·N with n21 = n2/n1.
// Returns nothing on total internal reflection (negative radicand).
inline std::optional<Vec3> refract(const Vec3& incident, const Vec3& normal, float n21) {
    const float cos_i = -glm::dot(incident, normal);
    const float radicand = 1.0f + (cos_i * cos_i - 1.0f) / (n21 * n21);
    if (radicand < 0.0f) return std::nullopt;
    return incident / n21 + (cos_i / n21 - std::sqrt(radicand)) * normal;
}

// Critical angle in radians for light going from a denser medium out (n21 = n_out/n_in < 1).
inline float critical_angle(float n21) {
    return std::asin(n21);
}

}  // namespace rayo
