#pragma once
// The Whitted integrator (seed 004's ray tree; seed 001's transport): at each hit the Phong
// local model with a shadow ray per light, plus recursive mirror reflection and Snell
// refraction, total internal reflection going to the reflected ray.
#include "core/accel.h"
#include "core/stats.h"
#include "shading/shading_scene.h"

namespace rayo {

struct WhittedSettings {
    int max_depth = 5;              // camera ray = depth 0; no child rays beyond this depth
    float min_contribution = 1e-3f; // children whose weight falls below this are not traced
};

class WhittedIntegrator {
public:
    WhittedIntegrator(const Accel& accel, const ShadingScene& scene, const WhittedSettings& s)
        : m_accel(accel), m_scene(scene), m_settings(s) {}

    // Radiance arriving along `ray` (a camera ray: counts it as such).
    Vec3 radiance(const Ray& ray, RayCounters& counters) const;

private:
    Vec3 trace(const Ray& ray, int depth, const Vec3& weight, RayCounters& counters) const;
    Vec3 shade(const Ray& ray, const SurfaceHit& hit, int depth, const Vec3& weight,
               RayCounters& counters) const;

    const Accel& m_accel;
    const ShadingScene& m_scene;
    WhittedSettings m_settings;
};

// Origin of a ray leaving `hit` on the side `side_normal` points to: offset along the
// geometric normal by an amount that scales with the hit position's magnitude and the object's
// size (DESIGN.md "Numerics": a fixed epsilon fails once coordinates reach ~1e3).
Vec3 offset_ray_origin(const SurfaceHit& hit, const Vec3& side_normal);

}  // namespace rayo
