#include "shading/integrators/whitted.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

#include "shading/media.h"
#include "shading/optics.h"
#include "shading/phong.h"

namespace rayo {
namespace {

float max_component(const Vec3& v) {
    return glm::max(v.x, glm::max(v.y, v.z));
}

}  // namespace

Vec3 WhittedIntegrator::radiance(const Ray& ray, RayCounters& counters) const {
    ++counters.camera;
    return trace(ray, 0, Vec3(1.0f), counters, nullptr);
}

Vec3 WhittedIntegrator::through_medium(const Vec3& radiance, float t,
                                       const SurfaceCoefficients* medium) const {
    if (medium)
        return medium->absorbing() ? radiance * beer_lambert(medium->absorption, t) : radiance;
    return m_scene.fog.enabled() ? m_scene.fog.apply(radiance, t) : radiance;
}

Vec3 WhittedIntegrator::through_volumes(const Ray& ray, float t_end, const Vec3& behind) const {
    const std::vector<const VoxelGrid*>& volumes = m_accel.volumes();
    if (volumes.empty()) return behind;
    float transmittance;
    const Vec3 colour = composite_volumes(volumes.data(), volumes.size(), ray.origin, ray.direction,
                                          ray.tnear, t_end, transmittance);
    return colour + transmittance * behind;
}

Vec3 WhittedIntegrator::unoccluded(const Ray& shadow) const {
    const std::vector<const VoxelGrid*>& volumes = m_accel.volumes();
    if (volumes.empty()) return Vec3(1.0f);
    float transmittance;
    composite_volumes(volumes.data(), volumes.size(), shadow.origin, shadow.direction, shadow.tnear,
                      shadow.tfar, transmittance);
    return Vec3(transmittance);
}

Vec3 WhittedIntegrator::trace(const Ray& ray, int depth, const Vec3& weight, RayCounters& counters,
                              const SurfaceCoefficients* medium) const {
    SurfaceHit hit;
    if (!m_accel.intersect(ray, hit)) return arriving(ray, nullptr, Vec3(0.0f), medium);
    if (depth == 0) ++counters.camera_hits;
    return arriving(ray, &hit, shade(ray, hit, depth, weight, counters, medium), medium);
}

Vec3 WhittedIntegrator::arriving(const Ray& ray, const SurfaceHit* hit, const Vec3& shaded,
                                 const SurfaceCoefficients* medium) const {
    if (!hit) {
        // A miss sees the environment or the background, or the pure fog colour (infinite
        // distance, seed 004).
        return through_volumes(
            ray, ray.tfar,
            !medium && m_scene.fog.enabled() ? m_scene.fog.color : m_scene.escaped(ray.direction));
    }
    return through_volumes(ray, hit->t, through_medium(shaded, hit->t, medium));
}

WhittedIntegrator::ShadingPoint WhittedIntegrator::prepare(
    const Ray& ray, const SurfaceHit& hit, const SurfaceCoefficients* medium) const {
    ShadingPoint p;
    m_surfaces.interact(ray, hit, p);
    p.medium = medium;
    if (m_radiosity) p.radiosity = m_radiosity->reflected(hit, p.entering, p.radiosity_reflected);
    return p;
}

Vec3 WhittedIntegrator::ambient_and_emission(const ShadingPoint& p) const {
    const SurfaceCoefficients& m = p.material();
    Vec3 color = p.radiosity ? p.radiosity_reflected : m.ka * m_scene.ambient_light;
    // An emitter is seen on its front, the side its geometric normal points to (the outside of
    // closed shapes, a disk's normal, a polygon's winding), and on its back when two-sided.
    if (m.emits_toward(p.entering)) color += m.emission;
    return color;
}

glm::vec2 WhittedIntegrator::sample_u(const SurfaceHit& hit, size_t index, int s, int count) {
    if (count == 1) return glm::vec2(0.5f);
    return light_sample_u(hit.position, static_cast<uint32_t>(index), static_cast<uint32_t>(s),
                          static_cast<uint32_t>(count));
}

template <typename L>
WhittedIntegrator::LightSide WhittedIntegrator::light_sample(const ShadingPoint& p,
                                                             const SurfaceHit& hit, const L& light,
                                                             int count, const glm::vec2& u,
                                                             Ray& shadow, Vec3& to_light,
                                                             Vec3& light_radiance) const {
    // Pure emitters skip the lights (other materials keep their shadow rays and counts as before).
    if (p.material().emissive() && !p.material().lit()) return LightSide::None;
    // An area light's surface shoots in the radiosity solve: its light is in the solution.
    if constexpr (kLightInRadiositySolve<L>) {
        if (p.radiosity) return LightSide::None;
    }
    LightSample sample;
    if (!light.sample(hit.position, u, sample)) return LightSide::None;
    to_light = sample.direction;
    const float light_distance = sample.distance;
    if constexpr (L::kDelta) {
        // A point or a direction: pdf 1, no emission image, the local model's scale 1 (below),
        // so the radiance is the sample's as it is (docs/performance.md, "Shading").
        light_radiance = sample.radiance;
    } else {
        light_radiance = light_sample_radiance(sample, m_images) / sample.pdf;
        // An area light is radiometric (radiance L, so the samples average to its irradiance
        // E): its light on a Lambertian surface is kd·E/π, the same the radiosity solve gives
        // it (docs/radiosity.md, "The π of area lights"). Point and directional lights keep
        // seed 000's Il, with no 1/π. The whole Phong term is scaled, so the highlight keeps its
        // ratio to the diffuse light.
        light_radiance *= kLightLocalModelScale<L>;
    }
    if (count > 1) light_radiance /= static_cast<float>(count);
    // Lights behind the surface (as seen from the arriving side) contribute nothing, unless the
    // surface is translucent and the light is wholly behind it (both normals agree).
    // With the shadow-terminator offset (core/shadow_terminator.h), the smooth surface decides
    // alone: a light below the flat triangle but above the interpolated normal's horizon is
    // seen from the lifted origin unless the mesh itself is in the way.
    const bool lifted =
        p.entering && m_settings.terminator_offset && hit.terminator_offset != Vec3(0.0f);
    LightSide side = LightSide::Front;
    if (glm::dot(p.normal, to_light) <= 0.0f ||
        (!lifted && glm::dot(p.facing_geometric, to_light) <= 0.0f)) {
        if (!p.material().translucent() || glm::dot(p.normal, to_light) >= 0.0f ||
            glm::dot(p.facing_geometric, to_light) >= 0.0f) {
            return LightSide::None;
        }
        side = LightSide::Back;
    }
    shadow.origin =
        side == LightSide::Front ? p.shadow_origin : offset_ray_origin(hit, -p.facing_geometric);
    if (side == LightSide::Front && lifted) shadow.origin += hit.terminator_offset;
    shadow.direction = to_light;
    shadow.tnear = 0.0f;
    // Stop just short of a point light so the light's own position is never "in the way".
    shadow.tfar = std::isfinite(light_distance) ? glm::dot(hit.position - shadow.origin, to_light) +
                                                      light_distance * (1.0f - 1e-5f)
                                                : std::numeric_limits<float>::infinity();
    if (sample.on_surface) {
        // A point on an emitter that is in the scene: aim from the offset origin at the point
        // itself (parallel to `to_light` the ray would meet the emitter's surface beside the
        // point, short of tfar, once the offset is large) and stop just short of it.
        const Vec3 offset = hit.position + light_distance * to_light - shadow.origin;
        const float length = glm::length(offset);
        shadow.direction = offset / length;
        shadow.tfar = length * (1.0f - 1e-5f);
    }
    return side;
}

Vec3 WhittedIntegrator::direct(const ShadingPoint& p, LightSide side, const Vec3& to_light,
                               const Vec3& light_radiance) {
    if (side == LightSide::Front) {
        return phong_direct(p.material(), p.normal, to_light, p.to_eye, light_radiance);
    }
    // seed 001: perfect diffuse transmission, by the cosine of the incidence angle on the far side.
    return light_radiance * p.material().translucency * -glm::dot(p.normal, to_light);
}

Vec3 WhittedIntegrator::shadow_transmittance(Ray shadow, RayCounters& counters) const {
    if (m_settings.shadows == ShadowMode::Opaque) {
        return m_accel.occluded(shadow) ? Vec3(0.0f) : unoccluded(shadow);
    }
    const Vec3 volumes = unoccluded(shadow);
    const Vec3 surfaces = filtered_transmittance(shadow, counters);
    return volumes == Vec3(1.0f) ? surfaces : volumes * surfaces;
}

Vec3 WhittedIntegrator::filtered_transmittance(Ray shadow, RayCounters& counters) const {
    // Filtered (POV-Ray's filtered shadows): closest-hit queries from each transmissive surface
    // to the next, multiplying its transmit colour, until the light or an opaque surface.
    Vec3 filter(1.0f);
    for (int crossing = 0;; ++crossing) {
        SurfaceHit hit;
        if (!m_accel.intersect(shadow, hit)) return filter;
        const Material& m = m_scene.materials[hit.material];
        if (!m.transmissive() || crossing == kMaxShadowCrossings) return Vec3(0.0f);
        filter *= m.transmit;
        const bool leaving = glm::dot(shadow.direction, hit.geometric_normal) > 0.0f;
        // Leaving an absorbing object: Beer–Lambert over the segment inside it (from the previous
        // crossing, or from the shadow ray's origin).
        if (leaving && m.absorbing()) filter *= beer_lambert(m.absorption, hit.t);
        if (max_component(filter) <= 0.0f) return Vec3(0.0f);
        ++counters.shadow_filtered;
        const Vec3 origin =
            offset_ray_origin(hit, leaving ? hit.geometric_normal : -hit.geometric_normal);
        shadow.tfar -= glm::dot(origin - shadow.origin, shadow.direction);
        shadow.origin = origin;
        if (!(shadow.tfar > 0.0f)) return filter;
    }
}

Vec3 WhittedIntegrator::shade(const Ray& ray, const SurfaceHit& hit, int depth, const Vec3& weight,
                              RayCounters& counters, const SurfaceCoefficients* medium) const {
    const ShadingPoint p = prepare(ray, hit, medium);
    // Local model, seed 003 eq. 2.9: I = ka·Ia + Σ f(d)·Il·[kd(n·l) + ks(…)^n], with a shadow ray
    // per light (seed 004), or per point of an area light.
    Vec3 color = ambient_and_emission(p);
    for (size_t index = 0; index < m_scene.lights.size(); ++index) {
        // One dispatch on the light's kind per light, not per sample (docs/performance.md,
        // "Shading").
        std::visit(
            [&](const auto& light) {
                const int count = light.sample_count();
                for (int s = 0; s < count; ++s) {
                    Ray shadow;
                    Vec3 to_light, light_radiance;
                    const LightSide side =
                        light_sample(p, hit, light, count, sample_u(hit, index, s, count), shadow,
                                     to_light, light_radiance);
                    if (side == LightSide::None) continue;
                    ++counters.shadow;
                    const Vec3 filter = shadow_transmittance(shadow, counters);
                    if (filter == Vec3(0.0f)) continue;
                    const Vec3 light_color = direct(p, side, to_light, light_radiance);
                    color += filter == Vec3(1.0f) ? light_color : filter * light_color;
                }
            },
            m_scene.lights[index]);
    }
    return add_transport(ray, hit, p, depth, weight, color, counters);
}

Vec3 WhittedIntegrator::add_transport(const Ray& ray, const SurfaceHit& hit, const ShadingPoint& p,
                                      int depth, const Vec3& weight, const Vec3& color,
                                      RayCounters& counters) const {
    const Transport t = plan_transport(ray, hit, p, depth, weight, counters);
    if (!t.children) return color;
    Vec3 transmitted(0.0f), reflected(0.0f);
    if (t.transmit) {
        transmitted =
            trace(t.transmit_ray, depth + 1, t.transmit_child_weight, counters, t.transmit_medium);
    }
    if (t.reflect) {
        reflected =
            trace(t.reflect_ray, depth + 1, t.reflect_child_weight, counters, t.reflect_medium);
    }
    return combine_transport(color, t, reflected, transmitted);
}

WhittedIntegrator::Transport WhittedIntegrator::plan_transport(const Ray& ray,
                                                               const SurfaceHit& hit,
                                                               const ShadingPoint& p, int depth,
                                                               const Vec3& weight,
                                                               RayCounters& counters) const {
    Transport t;
    const SurfaceCoefficients& material = p.material();
    if (!material.reflective() && !material.transmissive()) return t;
    if (depth >= m_settings.max_depth) {
        ++counters.depth_cut;
        return t;
    }
    t.children = true;

    // seed 001: perfect specular reflection R = I − 2(I·N)N, and Snell transmission; total
    // internal reflection sends the transmitted weight into the reflected ray.
    t.reflect_weight = material.reflect;
    t.transmit_weight = material.transmit;
    const float n21 = p.entering ? material.ior : 1.0f / material.ior;
    if (material.fresnel) {
        // seed 000's W(θ) as the dielectric Fresnel reflectance F: reflect·F and
        // transmit·(1 − F); F = 1 past the critical angle, so nothing is left to transmit.
        const float f = fresnel_reflectance(-glm::dot(ray.direction, p.normal), n21);
        t.reflect_weight *= f;
        t.transmit_weight *= 1.0f - f;
    }
    if (max_component(t.transmit_weight) > 0.0f) {
        const std::optional<Vec3> refracted = refract(ray.direction, p.normal, n21);
        if (refracted) {
            const Vec3 child_weight = weight * t.transmit_weight;
            if (max_component(child_weight) >= m_settings.min_contribution) {
                t.transmit = true;
                t.transmit_ray.origin = offset_ray_origin(hit, -p.facing_geometric);
                t.transmit_ray.direction = glm::normalize(*refracted);
                t.transmit_child_weight = child_weight;
                ++counters.refraction;
                // Entering an absorbing object, the child travels inside it (Beer–Lambert);
                // leaving, or through a material that absorbs nothing (a thin pane, clear
                // glass), it stays in the space between objects (the fog's).
                t.transmit_medium = p.entering && p.base->absorbing() ? p.base : nullptr;
            } else {
                ++counters.contribution_cut;
            }
        } else {
            ++counters.total_internal_reflections;
            t.reflect_weight += t.transmit_weight;
        }
    }
    if (max_component(t.reflect_weight) > 0.0f ||
        (m_settings.reflect_at_transmitters && material.transmissive())) {
        const Vec3 child_weight = weight * t.reflect_weight;
        if (max_component(child_weight) >= m_settings.min_contribution) {
            t.reflect = true;
            t.reflect_ray.origin = p.shadow_origin;
            t.reflect_ray.direction = glm::normalize(reflect(ray.direction, p.normal));
            t.reflect_child_weight = child_weight;
            t.reflect_medium = p.medium;
            ++counters.reflection;
        } else {
            ++counters.contribution_cut;
        }
    }
    return t;
}

Vec3 WhittedIntegrator::combine_transport(const Vec3& color, const Transport& t,
                                          const Vec3& reflected, const Vec3& transmitted) {
    const Vec3 transmit_color = t.transmit ? t.transmit_weight * transmitted : Vec3(0.0f);
    const Vec3 reflect_color = t.reflect ? t.reflect_weight * reflected : Vec3(0.0f);
    return color + reflect_color + transmit_color;
}

// One ray of the wavefront's ray tree (radiance_coherent): the ray, what its hit needs for
// shading, and where its children are.
struct WhittedIntegrator::PathNode {
    Ray ray;
    int depth = 0;
    Vec3 weight{1.0f};
    const SurfaceCoefficients* medium = nullptr;
    bool found = false;
    SurfaceHit hit;
    ShadingPoint point;
    Vec3 color{0.0f};  // the local model
    Transport transport;
    int reflect_child = -1, transmit_child = -1;  // indices in the node list
    Vec3 radiance{0.0f};                          // arriving along `ray`

    // A camera ray's node, reusing this one's storage: sets what the wavefront reads before it
    // writes it (hit, point, color and radiance are written first for every node that uses
    // them; transport only when `children` is set), instead of value-initialising the whole
    // node (about 0.5 KB) for every camera ray.
    void start(const Ray& camera_ray) {
        ray = camera_ray;
        depth = 0;
        weight = Vec3(1.0f);
        medium = nullptr;
        found = false;
        transport.children = false;
        reflect_child = transmit_child = -1;
    }
};

void WhittedIntegrator::intersect_level(std::vector<PathNode>& nodes, size_t begin,
                                        size_t end) const {
    // Camera rays are coherent; the children scatter (Embree's incoherent stream mode).
    constexpr int kBatch = Accel::kCoherentBatch;
    const Accel::Coherence coherence =
        nodes[begin].depth == 0 ? Accel::Coherence::Coherent : Accel::Coherence::Incoherent;
    Ray rays[kBatch];
    SurfaceHit hits[kBatch];
    bool found[kBatch];
    for (size_t first = begin; first < end; first += kBatch) {
        const int n = static_cast<int>(std::min<size_t>(kBatch, end - first));
        for (int i = 0; i < n; ++i) rays[i] = nodes[first + i].ray;
        m_accel.intersect_coherent(rays, n, hits, found, coherence);
        if (m_log) (nodes[begin].depth == 0 ? m_log->camera : m_log->secondary).add(rays, n);
        for (int i = 0; i < n; ++i) {
            nodes[first + i].found = found[i];
            if (found[i]) nodes[first + i].hit = hits[i];
        }
    }
}

void WhittedIntegrator::shade_level(std::vector<PathNode>& nodes, size_t begin, size_t end,
                                    RayCounters& counters) const {
    for (size_t k = begin; k < end; ++k) {
        PathNode& node = nodes[k];
        if (!node.found) continue;
        node.point = prepare(node.ray, node.hit, node.medium);
        node.color = ambient_and_emission(node.point);
    }
    // The local model's shadow rays (shade), a light sample at a time over the whole depth:
    // each hit's colour sums its light samples in the same order as shade does.
    constexpr int kBatch = Accel::kCoherentBatch;
    const Accel::Coherence coherence =
        nodes[begin].depth == 0 ? Accel::Coherence::Coherent : Accel::Coherence::Incoherent;
    Ray shadows[kBatch];
    Vec3 to_lights[kBatch], light_radiances[kBatch];
    LightSide sides[kBatch];
    size_t shadow_node[kBatch];
    bool occluded[kBatch];
    const auto flush = [&](int shadow_count) {
        counters.shadow += static_cast<uint64_t>(shadow_count);
        if (m_settings.shadows == ShadowMode::Opaque) {
            m_accel.occluded_coherent(shadows, shadow_count, occluded, coherence);
            if (m_log) {
                (nodes[begin].depth == 0 ? m_log->shadow_camera : m_log->shadow_secondary)
                    .add(shadows, shadow_count);
            }
        }
        for (int j = 0; j < shadow_count; ++j) {
            // Filtered shadows continue past surfaces ray by ray (shadow_transmittance): each
            // crossing is a closest-hit query whose next ray depends on the last one's hit.
            const Vec3 filter = m_settings.shadows == ShadowMode::Opaque
                                    ? (occluded[j] ? Vec3(0.0f) : unoccluded(shadows[j]))
                                    : shadow_transmittance(shadows[j], counters);
            if (filter == Vec3(0.0f)) continue;
            PathNode& node = nodes[shadow_node[j]];
            const Vec3 light_color = direct(node.point, sides[j], to_lights[j], light_radiances[j]);
            node.color += filter == Vec3(1.0f) ? light_color : filter * light_color;
        }
    };
    for (size_t index = 0; index < m_scene.lights.size(); ++index) {
        std::visit(
            [&](const auto& light) {
                const int samples = light.sample_count();
                for (int s = 0; s < samples; ++s) {
                    int shadow_count = 0;
                    for (size_t k = begin; k < end; ++k) {
                        const PathNode& node = nodes[k];
                        if (!node.found) continue;
                        const int j = shadow_count;
                        sides[j] = light_sample(node.point, node.hit, light, samples,
                                                sample_u(node.hit, index, s, samples), shadows[j],
                                                to_lights[j], light_radiances[j]);
                        if (sides[j] == LightSide::None) continue;
                        shadow_node[j] = k;
                        if (++shadow_count == kBatch) {
                            flush(shadow_count);
                            shadow_count = 0;
                        }
                    }
                    if (shadow_count > 0) flush(shadow_count);
                }
            },
            m_scene.lights[index]);
    }
}

void WhittedIntegrator::radiance_coherent(const Ray* rays, int count, Vec3* radiance,
                                          RayCounters& counters) const {
    // The same arithmetic as radiance() ray by ray, reordered as a wavefront over the ray tree
    // of each batch of camera rays: the rays of one depth are traced together, then their
    // shadow rays light sample by light sample, then their children form the next depth; the
    // radiance is summed back up the tree once every depth is traced, each hit combining its
    // children as add_transport does.
    constexpr int kBatch = Accel::kCoherentBatch;
    // The ray tree's nodes; kept per thread so that its storage is allocated once, not per batch.
    // A TBB thread-specific, not a thread_local: the first use of a thread_local with a
    // destructor registers it with the dynamic loader's lock held, which the image module's
    // background load holds for ~0.3 s (docs/performance.md "Fixed costs").
    static tbb::enumerable_thread_specific<std::vector<PathNode>> per_thread_nodes;
    std::vector<PathNode>& nodes = per_thread_nodes.local();
    for (int first = 0; first < count; first += kBatch) {
        const int n = std::min(kBatch, count - first);
        // The children of the last batch are dropped; the n camera nodes reuse their storage.
        if (nodes.size() > static_cast<size_t>(n)) {
            nodes.erase(nodes.begin() + n, nodes.end());
        } else {
            nodes.resize(static_cast<size_t>(n));
        }
        for (int i = 0; i < n; ++i) nodes[static_cast<size_t>(i)].start(rays[first + i]);
        counters.camera += static_cast<uint64_t>(n);
        for (size_t begin = 0; begin < nodes.size();) {
            const size_t end = nodes.size();
            intersect_level(nodes, begin, end);
            if (begin == 0) {
                for (size_t k = 0; k < end; ++k) counters.camera_hits += nodes[k].found ? 1 : 0;
            }
            shade_level(nodes, begin, end, counters);
            for (size_t k = begin; k < end; ++k) {
                if (!nodes[k].found) continue;
                if (!m_settings.stream_secondary) {
                    // The children one ray at a time, recursively (the single-ray path's own).
                    nodes[k].color =
                        add_transport(nodes[k].ray, nodes[k].hit, nodes[k].point, nodes[k].depth,
                                      nodes[k].weight, nodes[k].color, counters);
                    continue;
                }
                // add_transport's children: the refracted one first, as it counts them.
                Transport t = plan_transport(nodes[k].ray, nodes[k].hit, nodes[k].point,
                                             nodes[k].depth, nodes[k].weight, counters);
                const auto spawn = [&](const Ray& ray, const Vec3& weight,
                                       const SurfaceCoefficients* medium) {
                    PathNode child;
                    child.ray = ray;
                    child.depth = nodes[k].depth + 1;
                    child.weight = weight;
                    child.medium = medium;
                    nodes.push_back(std::move(child));
                    return static_cast<int>(nodes.size() - 1);
                };
                if (t.transmit) {
                    nodes[k].transmit_child =
                        spawn(t.transmit_ray, t.transmit_child_weight, t.transmit_medium);
                }
                if (t.reflect) {
                    nodes[k].reflect_child =
                        spawn(t.reflect_ray, t.reflect_child_weight, t.reflect_medium);
                }
                nodes[k].transport = t;
            }
            begin = end;
        }
        // Children come after their parents: summing back to front finishes each child first.
        for (size_t k = nodes.size(); k-- > 0;) {
            PathNode& node = nodes[k];
            if (!node.found) {
                node.radiance = arriving(node.ray, nullptr, Vec3(0.0f), node.medium);
                continue;
            }
            const Vec3 reflected = node.reflect_child >= 0
                                       ? nodes[static_cast<size_t>(node.reflect_child)].radiance
                                       : Vec3(0.0f);
            const Vec3 transmitted = node.transmit_child >= 0
                                         ? nodes[static_cast<size_t>(node.transmit_child)].radiance
                                         : Vec3(0.0f);
            const Vec3 shaded =
                node.transport.children
                    ? combine_transport(node.color, node.transport, reflected, transmitted)
                    : node.color;
            node.radiance = arriving(node.ray, &node.hit, shaded, node.medium);
        }
        for (int i = 0; i < n; ++i) radiance[first + i] = nodes[static_cast<size_t>(i)].radiance;
    }
}

}  // namespace rayo
