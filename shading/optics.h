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

// The dielectric Fresnel reflectance for unpolarized light (the W(θ) of seed 000's specular
// term, exact instead of a constant): light arriving at cos θi = `cos_i` (≥ 0) from the medium of
// index n1 onto the medium of index n2, n21 = n2/n1 (as refract). With Snell's cos θt,
//   rs = (n1 cos θi − n2 cos θt)/(n1 cos θi + n2 cos θt),
//   rp = (n1 cos θt − n2 cos θi)/(n1 cos θt + n2 cos θi),  R = (rs² + rp²)/2;
// R = 1 beyond the critical angle (total internal reflection). The transmitted fraction is 1 − R.
inline float fresnel_reflectance(float cos_i, float n21) {
    cos_i = glm::clamp(cos_i, 0.0f, 1.0f);
    const float sin_t2 = (1.0f - cos_i * cos_i) / (n21 * n21);
    if (sin_t2 >= 1.0f) return 1.0f;
    const float cos_t = std::sqrt(1.0f - sin_t2);
    // Divided through by n1: n1 = 1, n2 = n21.
    const float rs = (cos_i - n21 * cos_t) / (cos_i + n21 * cos_t);
    const float rp = (cos_t - n21 * cos_i) / (cos_t + n21 * cos_i);
    return 0.5f * (rs * rs + rp * rp);
}

// Critical angle in radians for light going from a denser medium out (n21 = n_out/n_in < 1).
inline float critical_angle(float n21) {
    return std::asin(n21);
}

}  // namespace rayo
