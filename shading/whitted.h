#pragma once
// The Whitted integrator (seed 004's ray tree; seed 001's transport): at each hit the Phong
// local model with a shadow ray per light, plus recursive mirror reflection and Snell
// refraction, total internal reflection going to the reflected ray.
#include <optional>

#include "core/accel.h"
#include "core/stats.h"
#include "shading/shading_scene.h"

namespace rayo {

struct WhittedSettings {
    int max_depth = 5;               // camera ray = depth 0; no child rays beyond this depth
    float min_contribution = 1e-3f;  // children whose weight falls below this are not traced
};

class WhittedIntegrator {
  public:
    WhittedIntegrator(const Accel& accel, const ShadingScene& scene, const WhittedSettings& s)
        : m_accel(accel), m_scene(scene), m_settings(s) {}

    // Radiance arriving along `ray` (a camera ray: counts it as such).
    Vec3 radiance(const Ray& ray, RayCounters& counters) const;
    // The same for a batch of coherent camera rays (a tile's): identical values ray by ray,
    // with the camera and shadow rays traced as Embree streams.
    void radiance_coherent(const Ray* rays, int count, Vec3* radiance, RayCounters& counters) const;

  private:
    // What shading a hit needs, computed once: the side the ray arrived on, normals after
    // bump mapping, the (textured) material, the spawned-ray origin.
    struct ShadingPoint {
        const SurfaceCoefficients* base = nullptr;    // the scene's material
        std::optional<SurfaceCoefficients> textured;  // its coefficients at the hit, if textured
        bool entering = true;
        Vec3 facing_geometric{0.0f}, normal{0.0f}, to_eye{0.0f}, shadow_origin{0.0f};
        // Not a stored pointer to `textured`: points are copied and must stay valid.
        const SurfaceCoefficients& material() const { return textured ? *textured : *base; }
    };
    ShadingPoint prepare(const Ray& ray, const SurfaceHit& hit) const;
    // The shadow ray toward `light`, the unit direction to it and its radiance at the hit;
    // false when the light is behind the surface.
    bool light_sample(const ShadingPoint& p, const SurfaceHit& hit, const Light& light, Ray& shadow,
                      Vec3& to_light, Vec3& light_radiance) const;
    // `color` (the local model) plus the reflected and refracted children (seed 001).
    Vec3 add_transport(const Ray& ray, const SurfaceHit& hit, const ShadingPoint& p, int depth,
                       const Vec3& weight, const Vec3& color, RayCounters& counters) const;

    Vec3 trace(const Ray& ray, int depth, const Vec3& weight, RayCounters& counters) const;
    Vec3 shade(const Ray& ray, const SurfaceHit& hit, int depth, const Vec3& weight,
               RayCounters& counters) const;

    const Accel& m_accel;
    const ShadingScene& m_scene;
    WhittedSettings m_settings;
};

// Origin of a ray leaving `hit` on the side `side_normal` points to: offset along the
// geometric normal by an amount that scales with the hit position's magnitude and the object's
// size (docs/architecture.md "Numerics": a fixed epsilon fails once coordinates reach ~1e3).
Vec3 offset_ray_origin(const SurfaceHit& hit, const Vec3& side_normal);

}  // namespace rayo
