#pragma once
// The Lambertian (perfectly diffuse) reflection lobe, seed 000 eq. [18] / seed 001 "perfect diffuse
// reflection" as a BRDF: f = albedo/π (Lambert 1760), sampled by the cosine (Malley's method).
#include <cmath>

#include "core/math.h"
#include "shading/scattering/local_frame.h"
#include "shading/scattering/scatter_sample.h"

namespace rayo {

// Two-sided: f = albedo/π whenever wi is on the same side as wo, whichever side that is.
class Lambert {
  public:
    static constexpr bool kDelta = false;
    Lambert() = default;
    explicit Lambert(const Vec3& albedo) : m_albedo(albedo) {}

    Vec3 eval(const Vec3& wo, const Vec3& wi) const {
        return same_hemisphere(wo, wi) ? m_albedo / kPi : Vec3(0.0f);
    }

    bool sample(const Vec3& wo, const glm::vec2& u, ScatterSample& out) const {
        if (wo.z == 0.0f) return false;
        Vec3 wi = sample_cosine_hemisphere(u);
        if (wo.z < 0.0f) wi = flip_z(wi);
        if (wi.z == 0.0f) return false;
        return smooth_sample(*this, wo, wi, out);
    }

    float pdf(const Vec3& wo, const Vec3& wi) const {
        return same_hemisphere(wo, wi) ? cosine_hemisphere_pdf(std::abs(wi.z)) : 0.0f;
    }

    // ∫ f |cos θi| dωi = albedo for every wo (the cosine integrates to π over the hemisphere).
    Vec3 albedo(const Vec3& wo) const { return wo.z != 0.0f ? m_albedo : Vec3(0.0f); }

  private:
    Vec3 m_albedo{0.0f};
};

}  // namespace rayo
