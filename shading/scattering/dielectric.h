#pragma once
// The smooth dielectric interface (glass, water): delta reflection and refraction, the branch
// chosen with the exact unpolarised Fresnel reflectance F (Fresnel 1823; shading/optics.h),
// refraction by seed 001's form of Snell's law (optics.h refract), total internal reflection beyond
// the critical angle.
#include <cmath>
#include <optional>

#include "core/math.h"
#include "shading/optics.h"
#include "shading/scattering/local_frame.h"
#include "shading/scattering/scatter_sample.h"

namespace rayo {

// The inside (z < 0) has index `ior`, the outside (z > 0) index 1; wo may be on either side.
// sample picks reflection when u.x < F(θo), refraction otherwise (reflection always
// under total internal reflection), so each branch's throughput factor value·|cos θi|/pdf is
// exactly 1: R + T = 1, and the estimator's expectation is F·reflected + (1 − F)·transmitted.
//
// Radiance scaling: the transmitted branch carries no 1/η² (η = ratio of the indices), the path
// tracer's choice. A path that enters and leaves the object picks up η² and 1/η², which cancel,
// so for cameras and lights outside the factor changes nothing, and without it the lobe is the
// same for radiance and importance (light tracing needs no separate mode). An emitter inside a
// dielectric is off by η² (a light inside glass of index 1.5 would come out 2.25× too bright);
// rayo's scenes put lights outside.
class Dielectric {
  public:
    static constexpr bool kDelta = true;  // its directions are a point set: eval and pdf 0
    Dielectric() = default;
    explicit Dielectric(float ior) : m_ior(ior) {}

    Vec3 eval(const Vec3&, const Vec3&) const { return Vec3(0.0f); }

    bool sample(const Vec3& wo, const glm::vec2& u, ScatterSample& out) const {
        if (wo.z == 0.0f) return false;
        const bool outside = wo.z > 0.0f;
        const float n21 = outside ? m_ior : 1.0f / m_ior;  // far side over wo's side (optics.h)
        const Vec3 normal(0.0f, 0.0f, outside ? 1.0f : -1.0f);  // faces wo, N·I < 0
        const float cos_o = std::abs(wo.z);
        float reflectance = fresnel_reflectance(cos_o, n21);
        std::optional<Vec3> transmitted;
        if (reflectance < 1.0f) transmitted = refract(-wo, normal, n21);
        // Rounding at the critical angle: a refraction that grazes the surface is reflection.
        if (!transmitted || transmitted->z * wo.z >= 0.0f) reflectance = 1.0f;
        out.delta = true;
        if (u.x < reflectance) {
            out.wi = reflect(-wo, normal);
            out.pdf = reflectance;
            out.value = Vec3(reflectance / cos_o);
        } else {
            out.wi = glm::normalize(*transmitted);
            out.pdf = 1.0f - reflectance;
            out.value = Vec3(out.pdf / std::abs(out.wi.z));
        }
        return true;
    }

    float pdf(const Vec3&, const Vec3&) const { return 0.0f; }

    // R + T: every photon is either reflected or transmitted.
    Vec3 albedo(const Vec3& wo) const { return wo.z != 0.0f ? Vec3(1.0f) : Vec3(0.0f); }

    // F for light along wo (the probability of the reflection branch).
    float reflectance(const Vec3& wo) const {
        return fresnel_reflectance(std::abs(wo.z), wo.z > 0.0f ? m_ior : 1.0f / m_ior);
    }

    float ior() const { return m_ior; }

  private:
    float m_ior = 1.5f;
};

}  // namespace rayo
