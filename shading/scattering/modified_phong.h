#pragma once
// The normalised modified Phong lobe of Lafortune & Willems 1994 ("Using the Modified Phong
// Reflectance Model for Physically Based Rendering"): seed 000 eq. [24]'s Ke·(V·R)ⁿ made a BRDF,
// f = ks·(n+2)/(2π)·cosⁿα, α between wi and the mirror direction of wo; sampled from cosⁿα.
#include <algorithm>
#include <cmath>

#include "core/math.h"
#include "shading/scattering/local_frame.h"
#include "shading/scattering/scatter_sample.h"

namespace rayo {

// The factor (n+2)/(2π) makes the albedo exactly ks at normal incidence (the lobe around the
// normal lies entirely above the horizon: ∫cosⁿα cos θ dω = 2π/(n+2)); at other angles part of the
// lobe falls below the horizon and is lost, so ∫ f cos θi dωi ≤ ks (Lafortune & Willems 1994,
// section 3). For large n the albedo at θo tends to ks·cos θo. Two-sided: wi on wo's side.
class ModifiedPhong {
  public:
    static constexpr bool kDelta = false;
    ModifiedPhong() = default;
    ModifiedPhong(const Vec3& ks, float exponent)
        : m_ks(ks), m_exponent(std::max(exponent, 0.0f)) {}

    Vec3 eval(const Vec3& wo, const Vec3& wi) const {
        const float c = cos_alpha(wo, wi);
        if (c <= 0.0f) return Vec3(0.0f);
        return m_ks * ((m_exponent + 2.0f) / (2.0f * kPi) * std::pow(c, m_exponent));
    }

    // cos α = u^(1/(n+1)) and φ = 2πu₂ about the mirror direction: the density (n+1)/(2π)·cosⁿα.
    // Directions below the horizon (or on the far side) are rejected: the pdf then integrates to
    // less than 1 over the hemisphere, which the estimator accounts for by returning false.
    bool sample(const Vec3& wo, const glm::vec2& u, ScatterSample& out) const {
        if (wo.z == 0.0f) return false;
        const LocalFrame lobe = LocalFrame::from_normal(mirror(wo));
        const float cos_a = std::pow(u.x, 1.0f / (m_exponent + 1.0f));
        const Vec3 wi = glm::normalize(lobe.to_world(spherical_direction(cos_a, 2.0f * kPi * u.y)));
        if (!same_hemisphere(wo, wi)) return false;
        return smooth_sample(*this, wo, wi, out);
    }

    float pdf(const Vec3& wo, const Vec3& wi) const {
        const float c = cos_alpha(wo, wi);
        if (c <= 0.0f) return 0.0f;
        return (m_exponent + 1.0f) / (2.0f * kPi) * std::pow(c, m_exponent);
    }

    float exponent() const { return m_exponent; }

  private:
    // seed 000 eq. [25]: R = 2(N·L)N − L, here about the local z: (−x, −y, z).
    static Vec3 mirror(const Vec3& w) { return Vec3(-w.x, -w.y, w.z); }
    // cos α = wi·R(wo) when wi is on wo's side, else 0 (symmetric in wo and wi: reciprocal).
    static float cos_alpha(const Vec3& wo, const Vec3& wi) {
        if (!same_hemisphere(wo, wi)) return 0.0f;
        return std::min(glm::dot(wi, mirror(wo)), 1.0f);
    }

    Vec3 m_ks{0.0f};
    float m_exponent = 1.0f;
};

}  // namespace rayo
