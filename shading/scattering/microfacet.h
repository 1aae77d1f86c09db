#pragma once
// The GGX / Trowbridge–Reitz microfacet reflection lobe (Trowbridge & Reitz 1975, Walter et al.
// 2007): D with isotropic α, height-correlated Smith G2 (Heitz 2014, "Understanding the Masking-
// Shadowing Function"), Schlick 1994 Fresnel, sampling of the visible normals (Heitz 2018).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/math.h"
#include "shading/scattering/local_frame.h"
#include "shading/scattering/scatter_sample.h"

namespace rayo {

// The smallest α the lobes use: below it D's peak 1/(πα²) and its float rounding make a smooth
// surface's highlight a handful of samples (α = 1e-3 gives D ≤ 3.2e5, still exact in float).
// A perfectly smooth surface is the Mirror or Dielectric lobe instead.
constexpr float kMinGgxAlpha = 1e-3f;

// D(h) = α² / (π (cos²θh (α² − 1) + 1)²)  (Walter et al. 2007, eq. 33), normalised so that
// ∫ D(h) cos θh dωh = 1; 0 below the horizon.
inline float ggx_d(float cos_h, float alpha) {
    if (cos_h <= 0.0f) return 0.0f;
    const float a2 = alpha * alpha;
    const float t = cos_h * cos_h * (a2 - 1.0f) + 1.0f;
    return a2 / (kPi * t * t);
}

// Smith's Λ for GGX: Λ(ω) = (−1 + √(1 + α² tan²θ))/2 (Heitz 2014); ∞ at the horizon.
inline float ggx_lambda(float cos_theta, float alpha) {
    const float c2 = cos_theta * cos_theta;
    if (c2 <= 0.0f) return std::numeric_limits<float>::infinity();
    const float tan2 = std::max(0.0f, 1.0f - c2) / c2;
    return 0.5f * (-1.0f + std::sqrt(1.0f + alpha * alpha * tan2));
}

// Masking G1(ω) = 1/(1 + Λ(ω)) (Heitz 2014) and the height-correlated masking-shadowing
// G2(wo, wi) = 1/(1 + Λ(wo) + Λ(wi)), both for directions above the surface.
inline float ggx_g1(float cos_theta, float alpha) {
    return cos_theta > 0.0f ? 1.0f / (1.0f + ggx_lambda(cos_theta, alpha)) : 0.0f;
}
inline float ggx_g2(float cos_o, float cos_i, float alpha) {
    if (cos_o <= 0.0f || cos_i <= 0.0f) return 0.0f;
    return 1.0f / (1.0f + ggx_lambda(cos_o, alpha) + ggx_lambda(cos_i, alpha));
}

// Schlick 1994: F = F0 + (1 − F0)(1 − cos θ)⁵ with cos θ = wo·h.
inline Vec3 schlick_fresnel(const Vec3& f0, float cos_theta) {
    const float m = 1.0f - glm::clamp(cos_theta, 0.0f, 1.0f);
    const float m2 = m * m;
    return f0 + (Vec3(1.0f) - f0) * (m2 * m2 * m);
}
inline float schlick_fresnel(float f0, float cos_theta) {
    const float m = 1.0f - glm::clamp(cos_theta, 0.0f, 1.0f);
    const float m2 = m * m;
    return f0 + (1.0f - f0) * (m2 * m2 * m);
}

// The density of visible normals D_wo(h) = G1(wo) max(0, wo·h) D(h) / cos θo (Heitz 2018);
// wo above the surface. It integrates to 1 over h for every wo.
inline float ggx_visible_normal_pdf(const Vec3& wo, const Vec3& h, float alpha) {
    const float o_h = glm::dot(wo, h);
    if (wo.z <= 0.0f || o_h <= 0.0f) return 0.0f;
    return ggx_g1(wo.z, alpha) * o_h * ggx_d(h.z, alpha) / wo.z;
}

// A microfacet normal drawn from D_wo (Heitz 2018, "Sampling the GGX Distribution of Visible
// Normals", JCGT): stretch wo to the configuration α = 1, where the visible normals are the
// projection of a uniform disk onto the hemisphere facing wo, with the disk's lower half squeezed
// by the projected hemisphere's edge; pick a point there and unstretch its normal. wo.z > 0.
inline Vec3 ggx_sample_visible_normal(const Vec3& wo, float alpha, const glm::vec2& u) {
    const Vec3 v = glm::normalize(Vec3(alpha * wo.x, alpha * wo.y, wo.z));
    // A basis (t1, t2, v) about the stretched view direction.
    const float len2 = v.x * v.x + v.y * v.y;
    const Vec3 t1 = len2 > 0.0f ? Vec3(-v.y, v.x, 0.0f) / std::sqrt(len2) : Vec3(1.0f, 0.0f, 0.0f);
    const Vec3 t2 = glm::cross(v, t1);
    // A uniform point of the unit disk (polar), its t2 coordinate squeezed toward the part of the
    // disk that the hemisphere's silhouette (a half ellipse of half-height v.z) leaves visible.
    const float r = std::sqrt(u.x);
    const float phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1.0f + v.z);
    const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
    // Lift onto the hemisphere and unstretch (normals transform by the inverse transpose).
    const Vec3 n = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * v;
    return glm::normalize(Vec3(alpha * n.x, alpha * n.y, std::max(0.0f, n.z)));
}

// f = F(wo·h) D(h) G2(wo, wi) / (4 cos θo cos θi), reflection only, sampled from the visible
// normals: pdf(wi) = D_wo(h)/(4 wo·h) = G1(wo) D(h)/(4 cos θo), so f cos θi/pdf = F·G2/G1 ≤ F.
// Two-sided: wo below the surface is evaluated as its mirror image above. Single scattering only:
// with F0 = 1 the albedo falls below 1 as α grows (energy lost to inter-reflection between facets).
class Microfacet {
  public:
    static constexpr bool kDelta = false;
    Microfacet() = default;
    Microfacet(float alpha, const Vec3& f0) : m_alpha(std::max(alpha, kMinGgxAlpha)), m_f0(f0) {}

    Vec3 eval(const Vec3& wo, const Vec3& wi) const {
        Vec3 o = wo, i = wi;
        if (!upper(o, i)) return Vec3(0.0f);
        const Vec3 h = glm::normalize(o + i);
        const float d = ggx_d(h.z, m_alpha);
        const float g = ggx_g2(o.z, i.z, m_alpha);
        return schlick_fresnel(m_f0, glm::dot(o, h)) * (d * g / (4.0f * o.z * i.z));
    }

    bool sample(const Vec3& wo, const glm::vec2& u, ScatterSample& out) const {
        if (wo.z == 0.0f) return false;
        const Vec3 o = wo.z > 0.0f ? wo : flip_z(wo);
        const Vec3 h = ggx_sample_visible_normal(o, m_alpha, u);
        const float o_h = glm::dot(o, h);
        if (o_h <= 0.0f) return false;
        Vec3 wi = glm::normalize(2.0f * o_h * h - o);
        if (wi.z <= 0.0f) return false;  // reflected below the horizon: no single-scattering path
        if (wo.z < 0.0f) wi = flip_z(wi);
        return smooth_sample(*this, wo, wi, out);
    }

    float pdf(const Vec3& wo, const Vec3& wi) const {
        Vec3 o = wo, i = wi;
        if (!upper(o, i)) return 0.0f;
        const Vec3 h = glm::normalize(o + i);
        const float o_h = glm::dot(o, h);
        if (o_h <= 0.0f) return 0.0f;
        return ggx_visible_normal_pdf(o, h, m_alpha) / (4.0f * o_h);
    }

    float alpha() const { return m_alpha; }
    const Vec3& f0() const { return m_f0; }

  private:
    static bool upper(Vec3& o, Vec3& i) {
        if (o.z < 0.0f) {
            o = flip_z(o);
            i = flip_z(i);
        }
        return o.z > 0.0f && i.z > 0.0f;
    }

    float m_alpha = 0.5f;
    Vec3 m_f0{1.0f};
};

}  // namespace rayo
