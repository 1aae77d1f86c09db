#pragma once
// The ambient-occlusion integrator (Tachyon's and VMD's "skylight"): at a camera ray's hit, the
// fraction of a cosine-weighted hemisphere of `samples` rays that escapes within `distance`,
// times the material's diffuse colour at the hit (textures and vertex colours included), plus, if
// asked, the direct light of the scene's lights (docs/references.md, ambient-occlusion). Rays
// that miss see the environment or the background. Registered in shading/integrators/integrator.h; its settings are
// its fields().
#include <optional>

#include "core/accel.h"
#include "core/sampler.h"
#include "core/setting.h"
#include "core/shapes/shape_fields.h"
#include "core/stats.h"
#include "shading/integrators/integrator_context.h"
#include "shading/surface_interaction.h"

namespace rayo {

class AmbientOcclusionIntegrator;

struct AmbientOcclusionSettings {
    static constexpr const char* kName = "ambient_occlusion";
    static constexpr const char* kSummary =
        "the unoccluded share of a cosine-weighted hemisphere times the diffuse colour "
        "(Tachyon's skylight), plus the lights' direct light if asked";
    using Integrator = AmbientOcclusionIntegrator;

    int samples = 16;       // hemisphere rays per camera sample
    float distance = 0.0f;  // occluders farther than this do not count; 0: unbounded
    bool direct = false;    // add the scene's lights (Lambert, with shadow rays)

    template <typename F>
    void fields(F& f) {
        f.integer({"samples", "hemisphere rays per camera sample", "--ao-samples"}, samples, 1,
                  4096);
        f.real({"distance", "occluders farther than this do not count; 0: any distance (unbounded)",
                "--ao-distance"},
               distance, 0.0, 1e30);
        f.toggle({"direct", "add the direct light of the scene's lights (Lambert, shadow rays)",
                  "--ao-direct"},
                 direct);
    }
    std::optional<FieldProblem> problem() const { return std::nullopt; }
};

class AmbientOcclusionIntegrator {
  public:
    AmbientOcclusionIntegrator(const IntegratorContext& context, const AmbientOcclusionSettings& s)
        : m_accel(context.accel),
          m_scene(context.scene),
          m_images(context.images),
          m_surfaces(context.accel, context.scene, context.images, context.pixel_spread),
          m_settings(s) {}

    // The tile loop's entries (core/render.h): the hemisphere's rays are stratified over the
    // camera sample's own dimensions of the sampler, so the image is the same for any thread
    // count, tile size or rank count.
    Vec3 radiance(const Ray& ray, const PixelSample& sample, RayCounters& counters) const;
    void radiance_coherent(const Ray* rays, const PixelSample* samples, int count, Vec3* out,
                           RayCounters& counters) const {
        for (int i = 0; i < count; ++i) out[i] = radiance(rays[i], samples[i], counters);
    }

  private:
    // The scene's lights at the hit, Lambert (kd/π·E for area lights, seed 000's kd·Il·(N·L)
    // for point, spot and directional lights, as Whitted shades them), with opaque shadows.
    Vec3 direct_light(const SurfaceHit& hit, const Vec3& normal, const Vec3& origin, const Vec3& kd,
                      const PixelSample& sample, RayCounters& counters) const;

    const Accel& m_accel;
    const ShadingScene& m_scene;
    const ImageTextures* m_images;
    SurfaceShading m_surfaces;
    AmbientOcclusionSettings m_settings;
};

}  // namespace rayo
