#pragma once
// What a scattering lobe's `sample` returns: the sampled direction wi with f(wo, wi) and its pdf,
// in the local shading frame (local_frame.h; z = shading normal, wo toward the viewer).
#include "core/math.h"

namespace rayo {

// For a smooth lobe, `value` is f(wo, wi) without the cosine and `pdf` the solid-angle density
// of wi, so the path throughput factor is value·|cos θi|/pdf. A delta lobe (mirror, smooth
// dielectric) keeps that product meaningful: `pdf` is the discrete probability of the branch it
// chose and `value` is (branch weight)·pdf/|cos θi|, so value·|cos θi|/pdf is the branch weight.
// Its eval and pdf are 0: no other sampling strategy can reach a delta direction.
struct ScatterSample {
    Vec3 wi{0.0f};     // sampled direction, unit, local frame
    Vec3 value{0.0f};  // f(wo, wi); for a delta lobe, weight·pdf/|cos θi| (see above)
    float pdf = 0.0f;  // solid-angle pdf; for a delta lobe, the probability of this branch
    bool delta = false;
};

// The sample of a smooth (non-delta) lobe in direction `wi`: its value and pdf are the lobe's
// eval and pdf there, so the two can never disagree. False where the pdf is 0.
template <typename Lobe>
bool smooth_sample(const Lobe& lobe, const Vec3& wo, const Vec3& wi, ScatterSample& out) {
    out.wi = wi;
    out.value = lobe.eval(wo, wi);
    out.pdf = lobe.pdf(wo, wi);
    out.delta = false;
    return out.pdf > 0.0f;
}

}  // namespace rayo
