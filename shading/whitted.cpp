#include "shading/whitted.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "shading/optics.h"
#include "shading/phong.h"

namespace rayo {
namespace {

float max_component(const Vec3& v) {
    return glm::max(v.x, glm::max(v.y, v.z));
}

// The texture of index `id`, or null for kNoTexture (render_scene has checked the ids).
const Texture* texture_at(const std::vector<Texture>& textures, int32_t id) {
    return id == kNoTexture ? nullptr : &textures[static_cast<size_t>(id)];
}

// The effective coefficients of a textured material at `position` (seed 003 ch. 3): each textured
// ka/kd/ks replaced by its texture's colour there.
SurfaceCoefficients material_at(const Material& m, const std::vector<Texture>& textures,
                                const Vec3& position) {
    SurfaceCoefficients local = m;
    const Texture* ka = texture_at(textures, m.textures.ka);
    const Texture* kd = texture_at(textures, m.textures.kd);
    const Texture* ks = texture_at(textures, m.textures.ks);
    if (kd) local.kd = kd->color(position);
    // ka often shares kd's texture (the default ka = 0.1 × kd): evaluate it once.
    if (ka) local.ka = m.textures.ka_scale * (ka == kd ? local.kd : ka->color(position));
    if (ks) local.ks = ks->color(position);
    return local;
}

}  // namespace

Vec3 offset_ray_origin(const SurfaceHit& hit, const Vec3& side_normal) {
    // eps = max(|P|∞, t, size)·k: about 80 float ulps of the largest magnitude involved, so the
    // new ray cannot re-hit the surface it leaves however far from the origin it lies.
    constexpr float kRelativeOffset = 1e-5f;
    const float scale = glm::max(max_abs_component(hit.position), glm::max(hit.t, hit.object_size));
    return hit.position + (kRelativeOffset * glm::max(scale, 1e-3f)) * side_normal;
}

Vec3 WhittedIntegrator::radiance(const Ray& ray, RayCounters& counters) const {
    ++counters.camera;
    return trace(ray, 0, Vec3(1.0f), counters);
}

Vec3 WhittedIntegrator::trace(const Ray& ray, int depth, const Vec3& weight,
                              RayCounters& counters) const {
    SurfaceHit hit;
    if (!m_accel.intersect(ray, hit)) return m_scene.background;
    return shade(ray, hit, depth, weight, counters);
}

WhittedIntegrator::ShadingPoint WhittedIntegrator::prepare(const Ray& ray,
                                                           const SurfaceHit& hit) const {
    ShadingPoint p;
    const Material& base = m_scene.materials[hit.material];
    // Which side the ray arrived on: seed 000 flips the normal for hits from inside (t1).
    p.entering = glm::dot(ray.direction, hit.geometric_normal) < 0.0f;
    p.facing_geometric = p.entering ? hit.geometric_normal : -hit.geometric_normal;
    p.normal = p.entering ? hit.shading_normal : -hit.shading_normal;
    p.base = &base;
    // Procedural textures (seed 003 ch. 3): untextured materials skip this and are used as is.
    if (base.textures.any()) {
        p.textured = material_at(base, m_scene.textures, hit.position);
        if (const Texture* bump = texture_at(m_scene.textures, base.textures.bump)) {
            p.normal = bump_normal(*bump, base.textures.bump_strength, hit.position, p.normal,
                                   p.facing_geometric);
        }
    }
    p.to_eye = -ray.direction;
    p.shadow_origin = offset_ray_origin(hit, p.facing_geometric);
    return p;
}

bool WhittedIntegrator::light_sample(const ShadingPoint& p, const SurfaceHit& hit,
                                     const Light& light, Ray& shadow, Vec3& to_light,
                                     Vec3& light_radiance) const {
    LightSample sample;
    if (!sample_light(light, hit.position, glm::vec2(0.5f), sample)) return false;
    to_light = sample.direction;
    const float light_distance = sample.distance;
    light_radiance = sample.radiance / sample.pdf;
    // Lights behind the surface (as seen from the arriving side) contribute nothing.
    if (glm::dot(p.normal, to_light) <= 0.0f || glm::dot(p.facing_geometric, to_light) <= 0.0f) {
        return false;
    }
    shadow.origin = p.shadow_origin;
    shadow.direction = to_light;
    shadow.tnear = 0.0f;
    // Stop just short of a point light so the light's own position is never "in the way".
    shadow.tfar =
        std::isfinite(light_distance)
            ? glm::dot(hit.position - p.shadow_origin, to_light) + light_distance * (1.0f - 1e-5f)
            : std::numeric_limits<float>::infinity();
    return true;
}

Vec3 WhittedIntegrator::shade(const Ray& ray, const SurfaceHit& hit, int depth, const Vec3& weight,
                              RayCounters& counters) const {
    const ShadingPoint p = prepare(ray, hit);
    // Local model, seed 003 eq. 2.1: I = ka·Ia + Σ f(d)·Il·[kd(n·l) + ks(…)^n], with a shadow ray
    // per light (seed 004).
    Vec3 color = p.material().ka * m_scene.ambient_light;
    for (const Light& light : m_scene.lights) {
        Ray shadow;
        Vec3 to_light, light_radiance;
        if (!light_sample(p, hit, light, shadow, to_light, light_radiance)) continue;
        ++counters.shadow;
        if (m_accel.occluded(shadow)) continue;
        color += phong_direct(p.material(), p.normal, to_light, p.to_eye, light_radiance);
    }
    return add_transport(ray, hit, p, depth, weight, color, counters);
}

Vec3 WhittedIntegrator::add_transport(const Ray& ray, const SurfaceHit& hit, const ShadingPoint& p,
                                      int depth, const Vec3& weight, const Vec3& color,
                                      RayCounters& counters) const {
    const SurfaceCoefficients& material = p.material();
    if (!material.reflective() && !material.transmissive()) return color;
    if (depth >= m_settings.max_depth) {
        ++counters.depth_cut;
        return color;
    }

    // seed 001: perfect specular reflection R = I − 2(I·N)N, and Snell transmission; total
    // internal reflection sends the transmitted weight into the reflected ray.
    Vec3 reflect_weight = material.reflect;
    Vec3 transmit_color(0.0f);
    if (material.transmissive()) {
        const float n21 = p.entering ? material.ior : 1.0f / material.ior;
        const std::optional<Vec3> refracted = refract(ray.direction, p.normal, n21);
        if (refracted) {
            const Vec3 child_weight = weight * material.transmit;
            if (max_component(child_weight) >= m_settings.min_contribution) {
                Ray child;
                child.origin = offset_ray_origin(hit, -p.facing_geometric);
                child.direction = glm::normalize(*refracted);
                ++counters.refraction;
                transmit_color =
                    material.transmit * trace(child, depth + 1, child_weight, counters);
            } else {
                ++counters.contribution_cut;
            }
        } else {
            ++counters.total_internal_reflections;
            reflect_weight += material.transmit;
        }
    }
    Vec3 reflect_color(0.0f);
    if (max_component(reflect_weight) > 0.0f) {
        const Vec3 child_weight = weight * reflect_weight;
        if (max_component(child_weight) >= m_settings.min_contribution) {
            Ray child;
            child.origin = p.shadow_origin;
            child.direction = glm::normalize(reflect(ray.direction, p.normal));
            ++counters.reflection;
            reflect_color = reflect_weight * trace(child, depth + 1, child_weight, counters);
        } else {
            ++counters.contribution_cut;
        }
    }
    return color + reflect_color + transmit_color;
}

void WhittedIntegrator::radiance_coherent(const Ray* rays, int count, Vec3* radiance,
                                          RayCounters& counters) const {
    // The same arithmetic as radiance() ray by ray, reordered so that each stage's rays go to
    // Embree together: camera rays, then the shadow rays toward each light in turn.
    constexpr int kBatch = Accel::kCoherentBatch;
    SurfaceHit hits[kBatch];
    bool found[kBatch];
    ShadingPoint points[kBatch];
    Vec3 color[kBatch];
    Ray shadows[kBatch];
    Vec3 to_lights[kBatch], light_radiances[kBatch];
    int shadow_pixel[kBatch];
    bool occluded[kBatch];
    for (int first = 0; first < count; first += kBatch) {
        const int n = std::min(kBatch, count - first);
        const Ray* batch = rays + first;
        counters.camera += static_cast<uint64_t>(n);
        m_accel.intersect_coherent(batch, n, hits, found);
        for (int i = 0; i < n; ++i) {
            if (!found[i]) continue;
            points[i] = prepare(batch[i], hits[i]);
            color[i] = points[i].material().ka * m_scene.ambient_light;
        }
        for (const Light& light : m_scene.lights) {
            int shadow_count = 0;
            for (int i = 0; i < n; ++i) {
                if (!found[i]) continue;
                const int k = shadow_count;
                if (!light_sample(points[i], hits[i], light, shadows[k], to_lights[k],
                                  light_radiances[k])) {
                    continue;
                }
                shadow_pixel[k] = i;
                ++shadow_count;
            }
            counters.shadow += static_cast<uint64_t>(shadow_count);
            m_accel.occluded_coherent(shadows, shadow_count, occluded);
            for (int k = 0; k < shadow_count; ++k) {
                if (occluded[k]) continue;
                const ShadingPoint& p = points[shadow_pixel[k]];
                color[shadow_pixel[k]] += phong_direct(p.material(), p.normal, to_lights[k],
                                                       p.to_eye, light_radiances[k]);
            }
        }
        for (int i = 0; i < n; ++i) {
            radiance[first + i] = found[i] ? add_transport(batch[i], hits[i], points[i], 0,
                                                           Vec3(1.0f), color[i], counters)
                                           : m_scene.background;
        }
    }
}

}  // namespace rayo
