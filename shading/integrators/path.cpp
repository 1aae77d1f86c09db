#include "shading/integrators/path.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shading/light.h"
#include "shading/media.h"
#include "shading/scattering/local_frame.h"
#include "shading/scattering/material_bsdf.h"

namespace rayo {

namespace {

// The power heuristic with β = 2 (Veach & Guibas 1995): the weight of the strategy with density
// `mine` against the other's `other`, each drawing one sample.
float power_heuristic(float mine, float other) {
    const float a = mine * mine, b = other * other;
    return a > 0.0f ? a / (a + b) : 0.0f;
}

// The sampler's dimensions of one bounce: the scattering function's pair, Russian roulette's
// one, one unused, then a pair per light.
constexpr uint32_t kBsdfDimension = 0;
constexpr uint32_t kRouletteDimension = 2;
constexpr uint32_t kFirstLightDimension = 4;

float max_component(const Vec3& v) {
    return std::max({v.x, v.y, v.z});
}

}  // namespace

// One scattering vertex: the surface interaction, its frame and scattering function.
struct PathIntegrator::Vertex {
    SurfaceHit hit;
    SurfaceInteraction surface;
    LocalFrame frame;  // z: the shading normal on the geometric normal's side (outside)
    Bsdf bsdf;
    Vec3 wo{0.0f};  // toward the previous vertex, local

    // Where a ray leaving along `direction` (world) starts: on the arriving side, or offset
    // through the surface for a transmitted one. False when the shading frame and the geometric
    // surface disagree about the side (a shading normal tilted past the surface): such a
    // direction would leak light through it.
    bool leave(const Vec3& direction, const Vec3& wi, Vec3& origin) const {
        const bool geometric_reflection = glm::dot(direction, surface.facing_geometric) > 0.0f;
        const bool shading_reflection = wi.z * wo.z > 0.0f;
        if (geometric_reflection != shading_reflection) return false;
        origin = geometric_reflection ? surface.shadow_origin
                                      : offset_ray_origin(hit, -surface.facing_geometric);
        return true;
    }
};

Vec3 PathIntegrator::radiance(const Ray& camera_ray, const PixelSample& sample,
                              RayCounters& counters) const {
    ++counters.camera;
    const uint32_t light_count = static_cast<uint32_t>(m_scene.lights.size());
    const uint32_t stride = kFirstLightDimension + 2 * light_count;
    const Fog& fog = m_scene.fog;
    Vec3 radiance(0.0f), throughput(1.0f);
    Ray ray = camera_ray;
    // The camera ray and rays after a delta lobe see emitters and the environment unweighted.
    bool specular = true;
    float bsdf_pdf = 0.0f;  // the solid-angle density of the last BSDF direction
    Vec3 previous_point(0.0f);
    const SurfaceCoefficients* medium = nullptr;  // the absorbing object the ray is inside
    Vertex v;
    for (int depth = 0;; ++depth) {
        const bool found = m_accel.intersect(ray, v.hit);
        // The segment's medium: Beer–Lambert inside an absorbing object, else the fog.
        if (medium) {
            if (found) throughput *= beer_lambert(medium->absorption, v.hit.t);
        } else if (fog.enabled()) {
            if (!found) {
                radiance += throughput * fog.color;
                break;
            }
            const float transmittance = std::exp(-fog.density * v.hit.t);
            radiance += throughput * fog.color * (1.0f - transmittance);
            throughput *= transmittance;
        }
        if (!found) {
            radiance += throughput * escaped(ray.direction, specular, bsdf_pdf, previous_point);
            break;
        }
        m_surfaces.interact(ray, v.hit, v.surface);
        const SurfaceCoefficients& material = v.surface.material();
        // An emitter is seen on its front, and on its back when two-sided (material.h).
        if (material.emits_toward(v.surface.entering)) {
            float weight = 1.0f;
            if (!specular && material.emitter_light >= 0) {
                if (m_settings.strategy == LightStrategy::Light) {
                    weight = 0.0f;
                } else if (m_settings.strategy == LightStrategy::Mis) {
                    const EmitterPoint at{v.hit.position, v.surface.facing_geometric,
                                          v.surface.base->emission};
                    const float light_density = light_pdf_at(m_scene.lights[material.emitter_light],
                                                             previous_point, ray.direction, at);
                    weight = power_heuristic(bsdf_pdf, light_density);
                }
            }
            radiance += throughput * material.emission * weight;
        }
        if (depth >= m_settings.max_depth) {
            ++counters.depth_cut;
            break;
        }
        v.bsdf = material_bsdf(material);
        if (v.bsdf.size() == 0) break;
        const Vec3 outside_normal = v.surface.entering ? v.surface.normal : -v.surface.normal;
        v.frame = LocalFrame::from_normal(outside_normal);
        v.wo = v.frame.to_local(v.surface.to_eye);
        const uint32_t dimension =
            kFirstIntegratorDimension + static_cast<uint32_t>(depth) * stride;
        if (v.bsdf.has_smooth_lobe()) {
            radiance += throughput * direct_light(v, sample, dimension, counters);
        }

        ScatterSample s;
        if (!v.bsdf.sample(v.wo, sample.get2d(dimension + kBsdfDimension), s)) break;
        const Vec3 direction = glm::normalize(v.frame.to_world(s.wi));
        Vec3 origin;
        if (!v.leave(direction, s.wi, origin)) break;
        throughput *= s.value * (std::abs(s.wi.z) / s.pdf);
        const bool transmitted = s.wi.z * v.wo.z < 0.0f;
        if (transmitted) {
            ++counters.refraction;
            // A transmit colour below 1 tints what the dielectric lets through (seed 001's
            // weight; the diffuse transmission lobe has its own colour); entering an absorbing
            // object the ray travels inside it, leaving it travels in the fog.
            if (s.delta && material.transmissive()) throughput *= material.transmit;
            medium = v.surface.entering && v.surface.base->absorbing() ? v.surface.base : nullptr;
        } else {
            ++counters.reflection;
        }
        specular = s.delta;
        bsdf_pdf = s.pdf;
        previous_point = v.hit.position;
        // Russian roulette: continue with probability q = min(1, max throughput component) and
        // divide by q, so the expectation is unchanged.
        if (depth + 1 >= m_settings.roulette_depth) {
            const float q = std::min(1.0f, max_component(throughput));
            if (!(sample.get1d(dimension + kRouletteDimension) < q)) {
                ++counters.contribution_cut;
                break;
            }
            throughput /= q;
        }
        ray.origin = origin;
        ray.direction = direction;
        ray.tnear = 0.0f;
        ray.tfar = std::numeric_limits<float>::infinity();
    }
    return radiance;
}

Vec3 PathIntegrator::escaped(const Vec3& direction, bool specular, float bsdf_pdf,
                             const Vec3& from) const {
    if (m_scene.environment < 0) return specular ? m_scene.background : Vec3(0.0f);
    const Light& light = m_scene.lights[size_t(m_scene.environment)];
    const Vec3 radiance = light_emitted(light, direction, EmitterPoint{});
    if (specular || m_settings.strategy == LightStrategy::Bsdf) return radiance;
    if (m_settings.strategy == LightStrategy::Light) return Vec3(0.0f);
    return radiance * power_heuristic(bsdf_pdf, light_pdf(light, from, direction));
}

Vec3 PathIntegrator::direct_light(const Vertex& v, const PixelSample& sample, uint32_t dimension,
                                  RayCounters& counters) const {
    Vec3 sum(0.0f);
    const Vec3& point = v.hit.position;
    for (size_t index = 0; index < m_scene.lights.size(); ++index) {
        const Light& light = m_scene.lights[index];
        const bool delta = light_is_delta(light);
        if (!delta && m_settings.strategy == LightStrategy::Bsdf) continue;
        const glm::vec2 u =
            sample.get2d(dimension + kFirstLightDimension + 2 * static_cast<uint32_t>(index));
        LightSample ls;
        if (!sample_light(light, point, u, ls)) continue;
        const Vec3 wi = v.frame.to_local(ls.direction);
        const Vec3 f = v.bsdf.eval(v.wo, wi);
        if (f == Vec3(0.0f)) continue;
        Vec3 origin;
        if (!v.leave(ls.direction, wi, origin)) continue;
        ++counters.shadow;
        if (m_accel.occluded(light_shadow_ray(point, origin, ls))) continue;
        float weight = 1.0f;
        if (!delta && m_settings.strategy == LightStrategy::Mis) {
            weight = power_heuristic(ls.pdf, v.bsdf.pdf(v.wo, wi));
        }
        Vec3 incident =
            light_sample_radiance(ls, m_images) * (light_radiometric_scale(light) / ls.pdf);
        // The fog between (a directional light's, at no distance, is not dimmed): what a BSDF
        // ray that finds the same emitter carries too, so the two strategies agree.
        // The environment, infinitely far, is hidden by fog as a BSDF ray that escapes sees it.
        if (m_scene.fog.enabled()) {
            if (std::isfinite(ls.distance)) {
                incident *= std::exp(-m_scene.fog.density * ls.distance);
            } else if (!delta) {
                continue;
            }
        }
        sum += f * incident * (std::abs(wi.z) * weight);
    }
    return sum;
}

}  // namespace rayo
