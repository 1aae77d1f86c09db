#include "shading/integrators/ambient_occlusion.h"

#include <cmath>
#include <limits>

#include "core/sampling.h"
#include "shading/light.h"
#include "shading/normal_mapping.h"
#include "shading/scattering/local_frame.h"
#include "shading/surface_interaction.h"

namespace rayo {

Vec3 AmbientOcclusionIntegrator::radiance(const Ray& ray, const PixelSample& sample,
                                          RayCounters& counters) const {
    ++counters.camera;
    SurfaceHit hit;
    if (!m_accel.intersect(ray, hit)) return m_scene.escaped(ray.direction);
    SurfaceInteraction surface;
    m_surfaces.interact(ray, hit, surface);
    const SurfaceCoefficients& material = surface.material();
    const Vec3 facing_geometric = surface.facing_geometric;
    const Vec3 normal = face_viewer(surface.normal, surface.to_eye);
    const Vec3 kd = material.kd;  // textured, times the vertex colour
    const Vec3 origin = surface.shadow_origin;
    const LocalFrame frame = LocalFrame::from_normal(normal);
    const float reach =
        m_settings.distance > 0.0f ? m_settings.distance : std::numeric_limits<float>::infinity();
    const auto count = static_cast<uint32_t>(m_settings.samples);
    uint32_t escaped = 0;
    for (uint32_t k = 0; k < count; ++k) {
        // Cosine-weighted by Malley's method: a uniform point of the unit disk lifted onto the
        // hemisphere (the concentric map keeps the strata compact).
        const glm::vec2 d =
            concentric_disk(sample.stratified2d(kFirstIntegratorDimension, k, count));
        const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
        Ray probe;
        probe.origin = origin;
        probe.direction = glm::normalize(frame.to_world(Vec3(d.x, d.y, z)));
        probe.tnear = 0.0f;
        probe.tfar = reach;
        // Below the geometric surface (a shading normal tilted past it): blocked by the surface.
        if (glm::dot(probe.direction, facing_geometric) <= 0.0f) continue;
        ++counters.shadow;
        if (!m_accel.occluded(probe)) ++escaped;
    }
    Vec3 color = kd * (static_cast<float>(escaped) / static_cast<float>(count));
    if (m_settings.direct) color += direct_light(hit, normal, origin, kd, sample, counters);
    if (material.emits_toward(surface.entering)) color += material.emission;
    return color;
}

Vec3 AmbientOcclusionIntegrator::direct_light(const SurfaceHit& hit, const Vec3& normal,
                                              const Vec3& origin, const Vec3& kd,
                                              const PixelSample& sample,
                                              RayCounters& counters) const {
    Vec3 sum(0.0f);
    for (size_t index = 0; index < m_scene.lights.size(); ++index) {
        const Light& light = m_scene.lights[index];
        const auto count = static_cast<uint32_t>(light_sample_count(light));
        // Each light's points from its own pair of the sampler's dimensions.
        const uint32_t dimension = kFirstIntegratorDimension + 2 + 2 * static_cast<uint32_t>(index);
        for (uint32_t s = 0; s < count; ++s) {
            LightSample ls;
            if (!sample_light(light, hit.position, sample.stratified2d(dimension, s, count), ls)) {
                continue;
            }
            const float cosine = glm::dot(normal, ls.direction);
            if (cosine <= 0.0f) continue;
            const Vec3 radiance =
                light_sample_radiance(ls, m_images) / ls.pdf * light_local_model_scale(light);
            ++counters.shadow;
            if (m_accel.occluded(light_shadow_ray(hit.position, origin, ls))) continue;
            sum += kd * radiance * cosine / static_cast<float>(count);
        }
    }
    return sum;
}

}  // namespace rayo
