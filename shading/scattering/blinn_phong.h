#pragma once
// A normalised Blinn–Phong lobe: seed 000 eq. [28]'s Ke·(N·H)ⁿ as a microfacet-style BRDF with
// D(h) = (n+2)/(2π)·cosⁿθh (Blinn 1977; normalised so ∫D cos θh dωh = 1) and the max(cos θo, cos
// θi) denominator of Ashikhmin & Shirley 2000; sampled by the half vector (Walter et al. 2007
// Jacobian).
#include <algorithm>
#include <cmath>

#include "core/math.h"
#include "shading/scattering/local_frame.h"
#include "shading/scattering/scatter_sample.h"

namespace rayo {

// f(wo, wi) = ks · D(h)·cos θh / (4 (wo·h) max(cos θo, cos θi)),  h = (wo + wi)/|wo + wi|.
// Why this form: with dωi = 4(wo·h) dωh (the reflection Jacobian),
//   ∫ f cos θi dωi = ks ∫ D(h) cos θh · cos θi/max(cos θo, cos θi) dωh ≤ ks ∫ D cos θh dωh = ks
// for every wo, it is reciprocal, and sampling h ∝ D(h) cos θh gives the bounded weight
// f cos θi/pdf = ks·cos θi/max(cos θo, cos θi) ≤ ks. (The plain D/(4 cos θo cos θi) diverges at
// grazing wo; RTR's (n+8)/(8π) cosⁿθh is not bounded by 1 for all wo.) At normal incidence the
// albedo is ks·[2(n+2)(1 − 2^(−(n+4)/2))/(n+4) − (1 − 2^(−(n+2)/2))] (tested). Two-sided.
class BlinnPhong {
  public:
    static constexpr bool kDelta = false;
    BlinnPhong() = default;
    BlinnPhong(const Vec3& ks, float exponent) : m_ks(ks), m_exponent(std::max(exponent, 0.0f)) {}

    Vec3 eval(const Vec3& wo, const Vec3& wi) const {
        Vec3 o = wo, i = wi;
        if (!upper(o, i)) return Vec3(0.0f);
        const Vec3 h = glm::normalize(o + i);
        const float o_h = glm::dot(o, h);
        if (o_h <= 0.0f || h.z <= 0.0f) return Vec3(0.0f);
        return m_ks * (half_vector_pdf(h.z) / (4.0f * o_h * std::max(o.z, i.z)));
    }

    // h from the density D(h) cos θh = (n+2)/(2π)·cos^(n+1)θh: cos θh = u^(1/(n+2)), then wi is
    // wo mirrored about h. Rejected when h faces away from wo or wi falls below the horizon.
    bool sample(const Vec3& wo, const glm::vec2& u, ScatterSample& out) const {
        if (wo.z == 0.0f) return false;
        const Vec3 o = wo.z > 0.0f ? wo : flip_z(wo);
        const float cos_h = std::pow(u.x, 1.0f / (m_exponent + 2.0f));
        const Vec3 h = spherical_direction(cos_h, 2.0f * kPi * u.y);
        const float o_h = glm::dot(o, h);
        if (o_h <= 0.0f) return false;
        Vec3 wi = glm::normalize(2.0f * o_h * h - o);
        if (wi.z <= 0.0f) return false;
        if (wo.z < 0.0f) wi = flip_z(wi);
        return smooth_sample(*this, wo, wi, out);
    }

    // pdf_h(h)/(4 wo·h): the half-vector density through the reflection Jacobian.
    float pdf(const Vec3& wo, const Vec3& wi) const {
        Vec3 o = wo, i = wi;
        if (!upper(o, i)) return 0.0f;
        const Vec3 h = glm::normalize(o + i);
        const float o_h = glm::dot(o, h);
        if (o_h <= 0.0f || h.z <= 0.0f) return 0.0f;
        return half_vector_pdf(h.z) / (4.0f * o_h);
    }

    float exponent() const { return m_exponent; }

  private:
    // D(h)·cos θh, the density the half vector is sampled from.
    float half_vector_pdf(float cos_h) const {
        return (m_exponent + 2.0f) / (2.0f * kPi) *
               std::pow(std::min(cos_h, 1.0f), m_exponent + 1.0f);
    }
    // Brings wo to the upper hemisphere (and wi with it); false unless both are then above.
    static bool upper(Vec3& o, Vec3& i) {
        if (o.z < 0.0f) {
            o = flip_z(o);
            i = flip_z(i);
        }
        return o.z > 0.0f && i.z > 0.0f;
    }

    Vec3 m_ks{0.0f};
    float m_exponent = 1.0f;
};

}  // namespace rayo
