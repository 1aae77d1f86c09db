#pragma once
// The Whitted integrator (seed 004's ray tree; seed 001's transport): at each hit the Phong
// local model with a shadow ray per light, plus recursive mirror reflection and Snell
// refraction, total internal reflection going to the reflected ray.
#include <optional>
#include <vector>

#include "core/accel.h"
#include "core/sampler.h"
#include "core/setting.h"
#include "core/shapes/shape_fields.h"
#include "core/stats.h"
#include "shading/image_texture.h"
#include "shading/integrators/integrator_context.h"
#include "shading/radiosity_field.h"
#include "shading/shading_scene.h"
#include "shading/surface_interaction.h"

namespace rayo {

// How shadow rays treat transmissive surfaces: Opaque stops at any surface; Filtered passes
// surfaces with a `transmit` colour, tinted by it at each crossing (POV-Ray's filtered shadows).
enum class ShadowMode { Opaque, Filtered };

// A filtered shadow ray crosses at most this many transmissive surfaces; one more is occlusion.
constexpr int kMaxShadowCrossings = 16;

class WhittedIntegrator;

// The Whitted integrator's settings: the first entry of the integrator registry
// (shading/integrators/integrator.h) and the default.
struct WhittedSettings {
    static constexpr const char* kName = "whitted";
    static constexpr const char* kSummary =
        "Whitted's ray tree: the Phong local model with a shadow ray per light sample, mirror "
        "reflection and refraction (seeds 000, 001)";
    using Integrator = WhittedIntegrator;

    int max_depth = 5;               // camera ray = depth 0; no child rays beyond this depth
    float min_contribution = 1e-3f;  // children whose weight falls below this are not traced
    ShadowMode shadows = ShadowMode::Opaque;
    // Shadow rays from smooth-shaded triangles start on the surface their vertex normals imply
    // (core/shadow_terminator.h; "render.shadow_terminator": "offset"), or on the flat triangle
    // ("none": the stair-step terminator of coarse meshes, kept for comparison).
    bool terminator_offset = true;
    // The angle one pixel's samples spread over, radians (the camera's pixel angle / √spp):
    // image textures filter over the footprint pixel_spread·t (docs/textures.md).
    float pixel_spread = 0.0f;
    // The coherent path (radiance_coherent) streams the camera rays and their shadow rays. With
    // stream_secondary its wavefront goes on past their hits: each depth's reflected and
    // refracted rays, then their shadow rays, as Embree streams (incoherent mode). That is not
    // bit-identical to single rays where triangles are hit (Embree's incoherent packet kernels
    // can report the other triangle at a shared edge: the default scene with mesh:2 spheres) and
    // not faster (docs/performance.md), so it is off: the recursion from the camera rays' hits
    // on traces one ray at a time.
    bool stream_secondary = false;
    // Transmitting surfaces spawn a reflection ray even when their mirror weight is 0 (then of
    // weight 0): the SPD's testing procedure counts a reflection ray at every hit on a reflecting
    // or transmitting surface (its Readme, "Testing Procedures" 8 and "Database Analysis"), and
    // the SPD's glass gears have Ks 0 (docs/performance.md, "The SPD's testing procedure").
    bool reflect_at_transmitters = false;

    // The scene-file and command-line settings (core/setting.h); pixel_spread and
    // stream_secondary are the render's and the benchmarks', not the user's.
    template <typename F>
    void fields(F& f) {
        f.integer({"max_depth", "maximum reflection/refraction depth"}, max_depth, 0, 64);
        f.real({"min_contribution",
                "children whose weight falls below this are not traced (seed 001's adaptive "
                "depth)"},
               min_contribution, 0.0, 1e30);
        f.choice({"shadows",
                  "opaque: any surface blocks a shadow ray; filtered: surfaces with a transmit "
                  "colour tint it (POV-Ray's filtered shadows)"},
                 shadows, {{"opaque", ShadowMode::Opaque}, {"filtered", ShadowMode::Filtered}});
        f.choice({"shadow_terminator",
                  "offset: shadow rays of smooth-shaded triangles start on the surface their "
                  "vertex normals imply (Hanika 2021); none: on the flat triangle"},
                 terminator_offset, {{"offset", true}, {"none", false}});
        f.toggle({"reflect_at_transmitters",
                  "transmitting surfaces always spawn a reflection ray, of weight 0 when their "
                  "reflect is 0 (the SPD's testing procedure counts one; the image is the same)"},
                 reflect_at_transmitters);
    }
    std::optional<FieldProblem> problem() const { return std::nullopt; }
};

// The rays of the coherent path's stream calls, call by call, by kind: what
// bench/stream_kinds_bench.cpp replays through rayo and through raw Embree. For one thread.
struct StreamLog {
    struct Calls {
        std::vector<Ray> rays;
        std::vector<int> sizes;  // rays per stream call, in order
        void add(const Ray* batch, int count) {
            rays.insert(rays.end(), batch, batch + count);
            sizes.push_back(count);
        }
    };
    Calls camera;            // closest hit, coherent
    Calls shadow_camera;     // occlusion from the camera rays' hits, coherent
    Calls shadow_secondary;  // occlusion from the reflected and refracted rays' hits, incoherent
    Calls secondary;         // closest hit of the reflected and refracted rays, incoherent
};

class WhittedIntegrator {
  public:
    // With a radiosity solution (docs/radiosity.md), each side of a patch-covered surface (the
    // front, and the back of a two-sided material) takes the radiance its patches reflect in
    // place of ka·Ia, and area lights (whose emitting surfaces are in the solve) give it no
    // direct light; point and directional lights, which are not in the solve, still do.
    // `images` holds the image textures of the scene's materials (shading/image_texture.h);
    // without it materials shade with their constant factors.
    WhittedIntegrator(const Accel& accel, const ShadingScene& scene, const WhittedSettings& s,
                      const RadiosityField* radiosity = nullptr,
                      const ImageTextures* images = nullptr)
        : m_accel(accel),
          m_scene(scene),
          m_settings(s),
          m_radiosity(radiosity),
          m_images(images),
          m_surfaces(accel, scene, images, s.pixel_spread) {}
    // The registry's constructor (shading/integrators/integrator.h).
    WhittedIntegrator(const IntegratorContext& context, WhittedSettings s)
        : WhittedIntegrator(context.accel, context.scene, with_spread(s, context.pixel_spread),
                            context.radiosity, context.images) {}

    // The tile loop's entries (core/render.h). Whitted's ray tree draws no random numbers but
    // its area lights' points, which it hashes from the shading point (shading/light.h
    // light_sample_u), so the pixel sample is not needed: the images stay what they were.
    Vec3 radiance(const Ray& ray, const PixelSample&, RayCounters& counters) const {
        return radiance(ray, counters);
    }
    void radiance_coherent(const Ray* rays, const PixelSample*, int count, Vec3* radiance,
                           RayCounters& counters) const {
        radiance_coherent(rays, count, radiance, counters);
    }

    // Radiance arriving along `ray` (a camera ray: counts it as such).
    Vec3 radiance(const Ray& ray, RayCounters& counters) const;
    // The same for a batch of coherent camera rays (a tile's): identical values ray by ray,
    // traced as a wavefront over the ray tree: each depth's rays, then their shadow rays toward
    // each light sample, as Embree streams (docs/performance.md, "Streams for every ray kind");
    // without stream_secondary the wavefront stops at the camera rays' hits.
    void radiance_coherent(const Ray* rays, int count, Vec3* radiance, RayCounters& counters) const;
    // Records the stream calls of radiance_coherent into `log` (null: stops); benchmarks only.
    void record_streams(StreamLog* log) { m_log = log; }

  private:
    static WhittedSettings with_spread(WhittedSettings s, float spread) {
        s.pixel_spread = spread;
        return s;
    }
    // What Whitted's shading of a hit needs: the surface interaction (shading/
    // surface_interaction.h), the medium the ray came through and the radiosity solution there.
    struct ShadingPoint : SurfaceInteraction {
        // The medium the arriving ray travelled through: the absorbing material whose inside it
        // crossed, or null for the space between objects (the fog's).
        const SurfaceCoefficients* medium = nullptr;
        // The radiance the radiosity solution reflects here, when the hit has one.
        bool radiosity = false;
        Vec3 radiosity_reflected{0.0f};
    };
    ShadingPoint prepare(const Ray& ray, const SurfaceHit& hit,
                         const SurfaceCoefficients* medium) const;
    // Which side of the surface a light sample lies on: the side the ray arrived on (the local
    // model), the far side of a translucent surface (diffuse transmission), or neither.
    enum class LightSide { None, Front, Back };
    // Sample u of `light` (one of `count`): the shadow ray toward it, the unit direction to it
    // and its radiance at the hit divided by the pdf and by `count`. Of one light type L, so
    // that a point or a directional light does only its own work (docs/performance.md,
    // "Shading").
    template <typename L>
    LightSide light_sample(const ShadingPoint& p, const SurfaceHit& hit, const L& light, int count,
                           const glm::vec2& u, Ray& shadow, Vec3& to_light,
                           Vec3& light_radiance) const;
    // The u of sample s of light `index` at the hit (light_sample_u; the centre for one sample).
    static glm::vec2 sample_u(const SurfaceHit& hit, size_t index, int s, int count);
    // The light the shading point reflects (Front: Phong) or transmits (Back: seed 001's
    // perfect diffuse transmission, translucency·(−N·L)) from one light sample.
    static Vec3 direct(const ShadingPoint& p, LightSide side, const Vec3& to_light,
                       const Vec3& light_radiance);
    // The fraction of light that reaches the end of `shadow`: 0 or 1 with opaque shadows; with
    // filtered shadows the product of the transmit colours of the surfaces it crosses (and the
    // Beer–Lambert absorption inside them), 0 at an opaque surface or past kMaxShadowCrossings.
    // Either times the transmittance of the composite voxel volumes the shadow ray crosses.
    Vec3 shadow_transmittance(Ray shadow, RayCounters& counters) const;
    // The filtered shadows' product over the surfaces alone.
    Vec3 filtered_transmittance(Ray shadow, RayCounters& counters) const;
    // The fraction of light a shadow ray that no surface blocks brings: 1, or the transmittance
    // of the composite voxel volumes it crosses (docs/voxels.md; grey: σ is one number).
    Vec3 unoccluded(const Ray& shadow) const;
    // The composite voxel volumes (docs/voxels.md) along `ray` up to t_end, front to back, over
    // the radiance `behind` them: C + T·behind (seed 004); `behind` itself when there are none.
    Vec3 through_volumes(const Ray& ray, float t_end, const Vec3& behind) const;
    // The radiance `radiance` of the point at distance `t` along a ray through `medium` as it
    // arrives: Beer–Lambert inside an absorbing material, the fog between objects (seed 004).
    Vec3 through_medium(const Vec3& radiance, float t, const SurfaceCoefficients* medium) const;
    // `color` (the local model) plus the reflected and refracted children (seed 001).
    Vec3 add_transport(const Ray& ray, const SurfaceHit& hit, const ShadingPoint& p, int depth,
                       const Vec3& weight, const Vec3& color, RayCounters& counters) const;
    // The children of a hit (seed 001), planned before they are traced so that the wavefront
    // can trace a whole depth's children together.
    struct Transport {
        bool children = false;                   // false: the hit's colour is its local model alone
        bool reflect = false, transmit = false;  // which child rays are traced
        Vec3 reflect_weight{0.0f}, transmit_weight{0.0f};
        Ray reflect_ray, transmit_ray;
        Vec3 reflect_child_weight{0.0f}, transmit_child_weight{0.0f};
        const SurfaceCoefficients* reflect_medium = nullptr;
        const SurfaceCoefficients* transmit_medium = nullptr;
    };
    Transport plan_transport(const Ray& ray, const SurfaceHit& hit, const ShadingPoint& p,
                             int depth, const Vec3& weight, RayCounters& counters) const;
    // The local `color` plus the children's radiance weighted (add_transport's sum).
    static Vec3 combine_transport(const Vec3& color, const Transport& t, const Vec3& reflected,
                                  const Vec3& transmitted);
    // The radiance arriving along `ray` from its hit (or its miss), given the hit's shaded colour
    // (trace's last step).
    Vec3 arriving(const Ray& ray, const SurfaceHit* hit, const Vec3& shaded,
                  const SurfaceCoefficients* medium) const;
    struct PathNode;
    // The wavefront's steps over the nodes [begin, end) of one depth: closest hits, then the
    // local model with the shadow rays of every light sample as streams.
    void intersect_level(std::vector<PathNode>& nodes, size_t begin, size_t end) const;
    void shade_level(std::vector<PathNode>& nodes, size_t begin, size_t end,
                     RayCounters& counters) const;

    Vec3 trace(const Ray& ray, int depth, const Vec3& weight, RayCounters& counters,
               const SurfaceCoefficients* medium) const;
    Vec3 shade(const Ray& ray, const SurfaceHit& hit, int depth, const Vec3& weight,
               RayCounters& counters, const SurfaceCoefficients* medium) const;
    // ka·Ia (or the radiosity solution's reflected radiance) plus the emission the ray sees (the
    // front side of an emissive surface).
    Vec3 ambient_and_emission(const ShadingPoint& p) const;

    const Accel& m_accel;
    const ShadingScene& m_scene;
    WhittedSettings m_settings;
    const RadiosityField* m_radiosity;
    const ImageTextures* m_images;
    SurfaceShading m_surfaces;
    StreamLog* m_log = nullptr;
};

}  // namespace rayo
