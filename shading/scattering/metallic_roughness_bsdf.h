#pragma once
// The glTF 2.0 metallic-roughness BRDF (glTF 2.0 spec appendix B, with the pseudocode as corrected
// in KhronosGroup/glTF#2392, 2024): a GGX metal with F0 = base colour, mixed by `metallic` with a
// dielectric that Fresnel-mixes (Schlick, F0 = 0.04) Lambert diffuse under a white GGX specular.
#include <algorithm>
#include <cmath>

#include "core/luminance.h"
#include "core/math.h"
#include "shading/scattering/local_frame.h"
#include "shading/scattering/microfacet.h"
#include "shading/scattering/scatter_sample.h"

namespace rayo {

// With s = D(h) G2(wo, wi)/(4 cos θo cos θi) (microfacet.h) and x = wo·h:
//   metal      = schlick(base, x) · s
//   dielectric = (1 − schlick(0.04, x)) · base/π + schlick(0.04, x) · s
//   f          = mix(dielectric, metal, metallic)
// α = roughness² (the spec), clamped to kMinGgxAlpha = 1e-3 so that roughness 0 stays finite
// and samplable (a true mirror is the Mirror lobe). Deviation from the spec's text: G2 is the
// height-correlated Smith form (Heitz 2014, docs/references.md). Like the spec's model it
// is single-scattering and does not conserve energy at grazing angles: the diffuse weight
// 1 − F(wo·h) is taken at the half vector of each wi (wo·h ≈ 0.7 for most of them) while the
// specular takes F(cos θo) ≈ 1, so the dielectric reflects more than it receives there: 1.71 at
// θo = 89° for a white base with roughness 0.1, 1.24 for base 0.5; ≤ 1 up to θo = 45° for any
// base ≤ 1 (measured in the tests). Sampled by choosing the specular (visible normals) or the
// diffuse (cosine) lobe with probability from the Fresnel-weighted luminances at wo; pdf is the
// mixture, so eval/pdf agree. Two-sided like the other reflection lobes.
class MetallicRoughnessBsdf {
  public:
    static constexpr bool kDelta = false;
    static constexpr float kDielectricF0 = 0.04f;  // glTF: ior 1.5, ((1.5 − 1)/(1.5 + 1))²

    MetallicRoughnessBsdf() = default;
    MetallicRoughnessBsdf(const Vec3& base_color, float metallic, float roughness)
        : m_base(base_color),
          m_metallic(glm::clamp(metallic, 0.0f, 1.0f)),
          m_alpha(std::max(roughness * roughness, kMinGgxAlpha)) {}

    Vec3 eval(const Vec3& wo, const Vec3& wi) const {
        Vec3 o = wo, i = wi;
        if (!upper(o, i)) return Vec3(0.0f);
        const Vec3 h = glm::normalize(o + i);
        const float x = glm::dot(o, h);
        const float s = ggx_d(h.z, m_alpha) * ggx_g2(o.z, i.z, m_alpha) / (4.0f * o.z * i.z);
        const float f_dielectric = schlick_fresnel(kDielectricF0, x);
        const Vec3 dielectric = (1.0f - f_dielectric) * m_base / kPi + Vec3(f_dielectric * s);
        const Vec3 metal = schlick_fresnel(m_base, x) * s;
        return glm::mix(dielectric, metal, m_metallic);
    }

    bool sample(const Vec3& wo, const glm::vec2& u, ScatterSample& out) const {
        if (wo.z == 0.0f) return false;
        const Vec3 o = wo.z > 0.0f ? wo : flip_z(wo);
        const float p = specular_probability(o.z);
        Vec3 wi;
        if (u.x < p) {
            const Vec3 h =
                ggx_sample_visible_normal(o, m_alpha, glm::vec2(remap_below(u.x, p), u.y));
            const float o_h = glm::dot(o, h);
            if (o_h <= 0.0f) return false;
            wi = glm::normalize(2.0f * o_h * h - o);
        } else {
            wi = sample_cosine_hemisphere(glm::vec2(remap_above(u.x, p), u.y));
        }
        if (wi.z <= 0.0f) return false;
        if (wo.z < 0.0f) wi = flip_z(wi);
        return smooth_sample(*this, wo, wi, out);
    }

    float pdf(const Vec3& wo, const Vec3& wi) const {
        Vec3 o = wo, i = wi;
        if (!upper(o, i)) return 0.0f;
        const float p = specular_probability(o.z);
        const Vec3 h = glm::normalize(o + i);
        const float o_h = glm::dot(o, h);
        const float specular =
            o_h > 0.0f ? ggx_visible_normal_pdf(o, h, m_alpha) / (4.0f * o_h) : 0.0f;
        return p * specular + (1.0f - p) * cosine_hemisphere_pdf(i.z);
    }

    // The probability of sampling the specular lobe: its Fresnel weight against the diffuse
    // lobe's, both as luminances, with F taken at the normal instead of the (unknown) half vector.
    float specular_probability(float cos_o) const {
        const float f_dielectric = schlick_fresnel(kDielectricF0, cos_o);
        const float specular =
            luminance(glm::mix(Vec3(f_dielectric), schlick_fresnel(m_base, cos_o), m_metallic));
        const float diffuse = (1.0f - m_metallic) * (1.0f - f_dielectric) * luminance(m_base);
        const float total = specular + diffuse;
        return total > 0.0f ? specular / total : 1.0f;
    }

    float alpha() const { return m_alpha; }

  private:
    static bool upper(Vec3& o, Vec3& i) {
        if (o.z < 0.0f) {
            o = flip_z(o);
            i = flip_z(i);
        }
        return o.z > 0.0f && i.z > 0.0f;
    }

    Vec3 m_base{0.8f};
    float m_metallic = 0.0f;
    float m_alpha = 0.25f;
};

}  // namespace rayo
