#pragma once
// A material's scattering function as a sum of up to kMaxLobes lobes (lambert.h ... metallic_
// roughness_bsdf.h), with no heap and no virtual call: a fixed array of std::variant, one lobe
// picked per sample by its selection weight (the one-sample model of Veach 1997, chapter 9).
#include <algorithm>
#include <array>
#include <variant>

#include "core/math.h"
#include "shading/scattering/blinn_phong.h"
#include "shading/scattering/dielectric.h"
#include "shading/scattering/diffuse_transmission.h"
#include "shading/scattering/lambert.h"
#include "shading/scattering/metallic_roughness_bsdf.h"
#include "shading/scattering/microfacet.h"
#include "shading/scattering/mirror.h"
#include "shading/scattering/modified_phong.h"
#include "shading/scattering/scatter_sample.h"

namespace rayo {

using Lobe = std::variant<Lambert, ModifiedPhong, BlinnPhong, Mirror, Dielectric,
                          DiffuseTransmission, Microfacet, MetallicRoughnessBsdf>;

constexpr int kMaxLobes = 4;

// f = Σ fᵢ (the lobes' own values: the weights only steer sampling). Lobe i is chosen with
// probability wᵢ/Σw. When a smooth lobe is chosen, the sample carries the full f of the smooth
// lobes and the mixture pdf Σ (wⱼ/Σw) pdfⱼ (what `pdf` returns), so a path tracer's MIS sees one
// density; a delta lobe's sample keeps its own value and multiplies its branch probability by
// wᵢ/Σw, so value·|cos θi|/pdf = (lobe's factor)·Σw/wᵢ (scatter_sample.h). Every lobe with a
// nonzero f needs a positive weight, or its directions are never sampled.
class Bsdf {
  public:
    // False (and nothing added) when full or the weight is not positive.
    bool add(const Lobe& lobe, float weight = 1.0f) {
        if (m_count == kMaxLobes || !(weight > 0.0f)) return false;
        m_lobes[m_count] = lobe;
        m_weights[m_count] = weight;
        m_total_weight += weight;
        ++m_count;
        return true;
    }

    int size() const { return m_count; }

    // Whether any lobe is smooth (not a delta): only then can light sampling find a direction
    // with a nonzero eval.
    bool has_smooth_lobe() const {
        for (int k = 0; k < m_count; ++k) {
            if (!std::visit([](const auto& l) { return std::decay_t<decltype(l)>::kDelta; },
                            m_lobes[k])) {
                return true;
            }
        }
        return false;
    }

    Vec3 eval(const Vec3& wo, const Vec3& wi) const {
        Vec3 f(0.0f);
        for (int k = 0; k < m_count; ++k) {
            f += std::visit([&](const auto& lobe) { return lobe.eval(wo, wi); }, m_lobes[k]);
        }
        return f;
    }

    float pdf(const Vec3& wo, const Vec3& wi) const {
        if (m_count == 0) return 0.0f;
        float p = 0.0f;
        for (int k = 0; k < m_count; ++k) {
            p += m_weights[k] *
                 std::visit([&](const auto& lobe) { return lobe.pdf(wo, wi); }, m_lobes[k]);
        }
        return p / m_total_weight;
    }

    bool sample(const Vec3& wo, const glm::vec2& u, ScatterSample& out) const {
        if (m_count == 0) return false;
        // Choose lobe k by u.x against the cumulative weights, and reuse u.x within its interval.
        const float x = u.x * m_total_weight;
        int k = 0;
        float below = 0.0f;
        while (k < m_count - 1 && x >= below + m_weights[k]) below += m_weights[k++];
        const glm::vec2 v(std::min(std::max(x - below, 0.0f) / m_weights[k], 0x1.fffffep-1f), u.y);
        const bool sampled =
            std::visit([&](const auto& lobe) { return lobe.sample(wo, v, out); }, m_lobes[k]);
        if (!sampled) return false;
        if (out.delta) {
            out.pdf *= m_weights[k] / m_total_weight;
            return out.pdf > 0.0f;
        }
        out.value = eval(wo, out.wi);
        out.pdf = pdf(wo, out.wi);
        return out.pdf > 0.0f;
    }

  private:
    std::array<Lobe, kMaxLobes> m_lobes{};
    std::array<float, kMaxLobes> m_weights{};
    float m_total_weight = 0.0f;
    int m_count = 0;
};

}  // namespace rayo
