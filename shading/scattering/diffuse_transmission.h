#pragma once
// Perfect diffuse transmission (seed 001: "like diffuse reflection, by the cosine of the incidence
// angle", from the other side): f = translucency/π on the hemisphere opposite wo, cosine sampled.
#include <cmath>

#include "core/math.h"
#include "shading/scattering/local_frame.h"
#include "shading/scattering/scatter_sample.h"

namespace rayo {

// Two-sided like Lambert: wi on the side opposite wo, whichever side wo is on.
class DiffuseTransmission {
  public:
    static constexpr bool kDelta = false;
    DiffuseTransmission() = default;
    explicit DiffuseTransmission(const Vec3& translucency) : m_translucency(translucency) {}

    Vec3 eval(const Vec3& wo, const Vec3& wi) const {
        return opposite(wo, wi) ? m_translucency / kPi : Vec3(0.0f);
    }

    bool sample(const Vec3& wo, const glm::vec2& u, ScatterSample& out) const {
        if (wo.z == 0.0f) return false;
        Vec3 wi = sample_cosine_hemisphere(u);
        if (wo.z > 0.0f) wi = flip_z(wi);
        if (wi.z == 0.0f) return false;
        return smooth_sample(*this, wo, wi, out);
    }

    float pdf(const Vec3& wo, const Vec3& wi) const {
        return opposite(wo, wi) ? cosine_hemisphere_pdf(std::abs(wi.z)) : 0.0f;
    }

    // ∫ f |cos θi| dωi over the far hemisphere = translucency.
    Vec3 albedo(const Vec3& wo) const { return wo.z != 0.0f ? m_translucency : Vec3(0.0f); }

  private:
    static bool opposite(const Vec3& a, const Vec3& b) { return a.z * b.z < 0.0f; }

    Vec3 m_translucency{0.0f};
};

}  // namespace rayo
