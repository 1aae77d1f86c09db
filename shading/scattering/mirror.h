#pragma once
// The perfect mirror, a delta lobe with a colour weight: seed 001's perfect specular reflection
// R = I − 2(I·N)N (shading/optics.h reflect), with I = −wo and N the local z.
#include <cmath>

#include "core/math.h"
#include "shading/optics.h"
#include "shading/scattering/local_frame.h"
#include "shading/scattering/scatter_sample.h"

namespace rayo {

// eval and pdf are 0 (no other strategy reaches the mirror direction). sample returns the only
// direction with pdf = 1 and value = weight/|cos θi|, so value·|cos θi|/pdf = weight, the factor
// the path throughput takes (scatter_sample.h). Two-sided: reflects on whichever side wo is.
class Mirror {
  public:
    static constexpr bool kDelta = true;  // its directions are a point set: eval and pdf 0
    Mirror() = default;
    explicit Mirror(const Vec3& weight) : m_weight(weight) {}

    Vec3 eval(const Vec3&, const Vec3&) const { return Vec3(0.0f); }

    bool sample(const Vec3& wo, const glm::vec2&, ScatterSample& out) const {
        if (wo.z == 0.0f) return false;
        // seed 001: the normal faces the incident side (N·I < 0).
        const Vec3 normal(0.0f, 0.0f, wo.z > 0.0f ? 1.0f : -1.0f);
        out.wi = reflect(-wo, normal);
        out.value = m_weight / std::abs(out.wi.z);
        out.pdf = 1.0f;
        out.delta = true;
        return true;
    }

    float pdf(const Vec3&, const Vec3&) const { return 0.0f; }

    // The reflected fraction of a mirror with weight w is w at every angle.
    Vec3 albedo(const Vec3& wo) const { return wo.z != 0.0f ? m_weight : Vec3(0.0f); }

  private:
    Vec3 m_weight{1.0f};
};

}  // namespace rayo
