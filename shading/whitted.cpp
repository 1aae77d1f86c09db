#include "shading/whitted.h"

#include <limits>
#include <optional>

#include "shading/optics.h"
#include "shading/phong.h"

namespace rayo {
namespace {

float max_component(const Vec3& v) {
    return glm::max(v.x, glm::max(v.y, v.z));
}

// The texture of index `id`, or null for kNoTexture (or an index the loaders would have refused).
const Texture* texture_at(const std::vector<Texture>& textures, int32_t id) {
    return id >= 0 && static_cast<size_t>(id) < textures.size() ? &textures[id] : nullptr;
}

// The effective coefficients of a textured material at `position` (seed 003 ch. 3): each textured
// ka/kd/ks replaced by its texture's colour there. Copies every other field but the name, so a
// hit allocates nothing.
Material material_at(const Material& m, const std::vector<Texture>& textures,
                     const Vec3& position) {
    Material local;
    const Texture* ka = texture_at(textures, m.textures.ka);
    const Texture* kd = texture_at(textures, m.textures.kd);
    const Texture* ks = texture_at(textures, m.textures.ks);
    local.kd = kd ? kd->color(position) : m.kd;
    // ka often shares kd's texture (the default ka = 0.1 × kd): evaluate it once.
    local.ka = ka ? m.textures.ka_scale * (ka == kd ? local.kd : ka->color(position)) : m.ka;
    local.ks = ks ? ks->color(position) : m.ks;
    local.shininess = m.shininess;
    local.specular_model = m.specular_model;
    local.reflect = m.reflect;
    local.transmit = m.transmit;
    local.ior = m.ior;
    local.textures = m.textures;
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

Vec3 WhittedIntegrator::shade(const Ray& ray, const SurfaceHit& hit, int depth, const Vec3& weight,
                              RayCounters& counters) const {
    const Material& base = m_scene.materials[hit.material];
    // Which side the ray arrived on: seed 000 flips the normal for hits from inside (t1).
    const bool entering = glm::dot(ray.direction, hit.geometric_normal) < 0.0f;
    const Vec3 facing_geometric = entering ? hit.geometric_normal : -hit.geometric_normal;
    Vec3 normal = entering ? hit.shading_normal : -hit.shading_normal;
    // Procedural textures (seed 003 ch. 3): untextured materials skip this and are used as is.
    std::optional<Material> textured;
    if (base.textures.any()) {
        textured.emplace(material_at(base, m_scene.textures, hit.position));
        if (const Texture* bump = texture_at(m_scene.textures, base.textures.bump)) {
            normal = bump_normal(*bump, base.textures.bump_strength, hit.position, normal,
                                 facing_geometric);
        }
    }
    const Material& material = textured ? *textured : base;
    const Vec3 to_eye = -ray.direction;

    // Local model, seed 003 eq. 2.1: I = ka·Ia + Σ f(d)·Il·[kd(n·l) + ks(…)^n], with a shadow ray
    // per light (seed 004).
    Vec3 color = material.ka * m_scene.ambient_light;
    const Vec3 shadow_origin = offset_ray_origin(hit, facing_geometric);
    for (const Light& light : m_scene.lights) {
        Vec3 to_light;
        float light_distance;
        Vec3 light_radiance;
        if (const auto* point = std::get_if<PointLight>(&light)) {
            const Vec3 offset = point->position - hit.position;
            light_distance = glm::length(offset);
            if (!(light_distance > 0.0f)) continue;
            to_light = offset / light_distance;
            light_radiance =
                point->color * point->intensity * point->attenuation.factor(light_distance);
        } else {
            const auto& directional = std::get<DirectionalLight>(light);
            to_light = -directional.direction;
            light_distance = std::numeric_limits<float>::infinity();
            light_radiance = directional.color * directional.intensity;
        }
        // Lights behind the surface (as seen from the arriving side) contribute nothing.
        if (glm::dot(normal, to_light) <= 0.0f || glm::dot(facing_geometric, to_light) <= 0.0f) {
            continue;
        }
        Ray shadow;
        shadow.origin = shadow_origin;
        shadow.direction = to_light;
        shadow.tnear = 0.0f;
        // Stop just short of a point light so the light's own position is never "in the way".
        shadow.tfar =
            std::isfinite(light_distance)
                ? glm::dot(hit.position - shadow_origin, to_light) + light_distance * (1.0f - 1e-5f)
                : std::numeric_limits<float>::infinity();
        ++counters.shadow;
        if (m_accel.occluded(shadow)) continue;
        color += phong_direct(material, normal, to_light, to_eye, light_radiance);
    }

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
        const float n21 = entering ? material.ior : 1.0f / material.ior;
        const std::optional<Vec3> refracted = refract(ray.direction, normal, n21);
        if (refracted) {
            const Vec3 child_weight = weight * material.transmit;
            if (max_component(child_weight) >= m_settings.min_contribution) {
                Ray child;
                child.origin = offset_ray_origin(hit, -facing_geometric);
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
            child.origin = shadow_origin;
            child.direction = glm::normalize(reflect(ray.direction, normal));
            ++counters.reflection;
            reflect_color = reflect_weight * trace(child, depth + 1, child_weight, counters);
        } else {
            ++counters.contribution_cut;
        }
    }
    return color + reflect_color + transmit_color;
}

}  // namespace rayo
