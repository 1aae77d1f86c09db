#pragma once
// The path integrator: unidirectional path tracing of the rendering equation (Kajiya 1986) with
// the materials' scattering functions (shading/scattering/material_bsdf.h). At every vertex
// whose lobe is not a delta, next-event estimation samples each of the scene's lights once, and
// the scattering function samples the next direction; the two estimates of an extended light
// (area lights, emissive meshes) are combined by multiple importance sampling with the power
// heuristic (Veach & Guibas 1995). Delta lobes (mirror, glass, seed 001) carry the light they
// find unweighted. Russian roulette ends paths after `roulette_depth` bounces with an unbiased
// weight. Beer–Lambert absorption inside dielectrics and the scene's fog as Whitted applies them
// (seed 004). Rays that escape see the environment light, which lights the scene as every other
// light; without one, the background colour from the camera and through delta bounces only: it
// is a backdrop, not a light (docs/path-tracing.md). Registered in
// shading/integrators/integrator.h; its settings are its fields().
#include <optional>
#include <vector>

#include "core/accel.h"
#include "core/sampler.h"
#include "core/setting.h"
#include "core/shapes/shape_fields.h"
#include "core/stats.h"
#include "shading/integrators/integrator_context.h"
#include "shading/surface_interaction.h"

namespace rayo {

class PathIntegrator;

// Which estimators of an extended light's direct light the path integrator adds up.
enum class LightStrategy {
    Mis,    // light sampling and BSDF sampling, weighted by the power heuristic
    Light,  // light sampling only (emitters that no light samples are still found by BSDF rays)
    Bsdf,   // BSDF sampling only (point, spot and directional lights are still sampled)
};

struct PathSettings {
    static constexpr const char* kName = "path";
    static constexpr const char* kSummary =
        "path tracing: every light and every lobe, light and BSDF sampling combined by multiple "
        "importance sampling, Russian roulette";
    using Integrator = PathIntegrator;

    int max_depth = 12;      // scattering events on a path at most (1: direct light only)
    int roulette_depth = 3;  // bounces before Russian roulette may end a path
    LightStrategy strategy = LightStrategy::Mis;

    template <typename F>
    void fields(F& f) {
        f.integer({"max_depth", "scattering events on a path at most (1: direct light only)"},
                  max_depth, 1, 1024);
        f.integer({"roulette_depth",
                   "bounces before Russian roulette may end a path (unbiased either way)"},
                  roulette_depth, 0, 1024);
        f.choice({"strategy",
                  "how area lights and emitters are found: mis (light and BSDF sampling, power "
                  "heuristic), light (light sampling only), bsdf (BSDF sampling only); for "
                  "comparisons, mis is the one to render with",
                  "--light-strategy"},
                 strategy,
                 {{"mis", LightStrategy::Mis},
                  {"light", LightStrategy::Light},
                  {"bsdf", LightStrategy::Bsdf}});
    }
    std::optional<FieldProblem> problem() const { return std::nullopt; }
};

// The rays of a path-traced frame by kind, in the order they were traced: what
// bench/stream_kinds_bench.cpp replays through rayo's Accel and through raw Embree. One thread.
struct PathRayLog {
    std::vector<Ray> camera;  // closest hit
    std::vector<Ray> bounce;  // closest hit: the rays a scattering function sampled
    std::vector<Ray> shadow;  // occlusion: next-event estimation toward a light sample
};

class PathIntegrator {
  public:
    PathIntegrator(const IntegratorContext& context, const PathSettings& s)
        : m_accel(context.accel),
          m_scene(context.scene),
          m_images(context.images),
          m_surfaces(context.accel, context.scene, context.images, context.pixel_spread),
          m_settings(s) {}

    // The tile loop's entries (core/render.h). Every random number of a path is drawn from the
    // camera sample's own dimensions of the sampler (a fixed block per bounce), so the image is
    // the same for any thread count, tile size or rank count.
    Vec3 radiance(const Ray& ray, const PixelSample& sample, RayCounters& counters) const;
    // The same for a batch of camera rays, identical values path by path, traced as a wavefront:
    // each round's rays of all live paths as one Embree stream, then their shadow rays as
    // streams (docs/path-tracing.md, "Streams").
    void radiance_coherent(const Ray* rays, const PixelSample* samples, int count, Vec3* out,
                           RayCounters& counters) const;

    // Records every ray radiance() traces into `log` (null: stops); benchmarks only.
    void record_rays(PathRayLog* log) { m_log = log; }

  private:
    struct Vertex;
    struct PathState;
    struct LightSampleAt;
    // A path's steps from one ray to the next (radiance() and the wavefront take the same):
    // arrive: what the ray found (its medium, the environment or an emitter it sees, the
    // vertex's scattering function); false when the path ends there.
    bool arrive(PathState& path, bool found, RayCounters& counters) const;
    // Next-event estimation, one light at a time: a sample of light `index` whose shadow ray is
    // to be traced (false: it gives nothing), then, once the ray is unoccluded, its light added
    // to `sum`, weighted against BSDF sampling where both can find the light.
    bool sample_light_at(const PathState& path, size_t index, LightSampleAt& at,
                         RayCounters& counters) const;
    void add_light(const PathState& path, const LightSampleAt& at, Vec3& sum) const;
    // scatter: the scattering function's sample, Russian roulette and the next ray; false when
    // the path ends there.
    bool scatter(PathState& path, RayCounters& counters) const;

    // What a path that leaves the scene along `direction` after a vertex at `from` gains (before
    // its throughput): the environment, weighted against light sampling unless the last bounce
    // was a delta (`specular`, or the camera ray).
    Vec3 escaped(const Vec3& direction, bool specular, float bsdf_pdf, const Vec3& from) const;

    const Accel& m_accel;
    const ShadingScene& m_scene;
    const ImageTextures* m_images;
    SurfaceShading m_surfaces;
    PathSettings m_settings;
    PathRayLog* m_log = nullptr;
};

}  // namespace rayo
