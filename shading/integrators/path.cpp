#include "shading/integrators/path.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

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

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

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

// A path between its bounces: what radiance() keeps from one vertex to the next, and what the
// wavefront (radiance_coherent) keeps for each of its paths.
struct PathIntegrator::PathState {
    Ray ray;  // the next ray to trace
    PixelSample sample;
    Vec3 radiance{0.0f}, throughput{1.0f};
    // The camera ray and rays after a delta lobe see emitters and the environment unweighted.
    bool specular = true;
    float bsdf_pdf = 0.0f;  // the solid-angle density of the last BSDF direction
    Vec3 previous_point{0.0f};
    const SurfaceCoefficients* medium = nullptr;  // the absorbing object the ray is inside
    int depth = 0;
    uint32_t dimension = 0;  // the sampler's first dimension of this vertex
    Vertex v;

    void start(const Ray& camera_ray, const PixelSample& pixel_sample) {
        ray = camera_ray;
        sample = pixel_sample;
        radiance = Vec3(0.0f);
        throughput = Vec3(1.0f);
        specular = true;
        bsdf_pdf = 0.0f;
        previous_point = Vec3(0.0f);
        medium = nullptr;
        depth = 0;
    }
};

// A light sample of next-event estimation whose shadow ray is still to be traced: what its
// contribution needs once the ray is found unoccluded.
struct PathIntegrator::LightSampleAt {
    size_t light = 0;
    LightSample sample;
    Vec3 wi{0.0f};  // toward the light, local
    Vec3 f{0.0f};   // the scattering function there
    Ray shadow;
};

Vec3 PathIntegrator::radiance(const Ray& camera_ray, const PixelSample& sample,
                              RayCounters& counters) const {
    ++counters.camera;
    PathState path;
    path.start(camera_ray, sample);
    for (;;) {
        if (m_log) (path.depth == 0 ? m_log->camera : m_log->bounce).push_back(path.ray);
        const bool found = m_accel.intersect(path.ray, path.v.hit);
        if (!arrive(path, found, counters)) break;
        if (path.v.bsdf.has_smooth_lobe()) {
            Vec3 direct(0.0f);
            for (size_t index = 0; index < m_scene.lights.size(); ++index) {
                LightSampleAt at;
                if (!sample_light_at(path, index, at, counters)) continue;
                if (m_log) m_log->shadow.push_back(at.shadow);
                if (m_accel.occluded(at.shadow)) continue;
                add_light(path, at, direct);
            }
            path.radiance += path.throughput * direct;
        }
        if (!scatter(path, counters)) break;
    }
    return path.radiance;
}

void PathIntegrator::radiance_coherent(const Ray* rays, const PixelSample* samples, int count,
                                       Vec3* out, RayCounters& counters) const {
    // The same arithmetic as radiance() path by path, reordered as a wavefront over a batch of
    // camera rays: each round traces the live paths' rays as one Embree stream, then their
    // shadow rays toward every light sample as streams, then samples each path's next ray
    // (docs/path-tracing.md, "Streams"). Per thread, so that the paths' storage is allocated
    // once (a TBB thread-specific, as Whitted's wavefront keeps its nodes).
    constexpr int kBatch = Accel::kCoherentBatch;
    struct Wavefront {
        std::vector<PathState> paths;
        std::vector<int> live;
        std::vector<LightSampleAt> lights;  // this round's light samples, path by path
        std::vector<int> light_path;        // the path of each
        std::vector<Vec3> direct;           // per path, this round's direct light
        std::vector<char> has_direct;
    };
    static tbb::enumerable_thread_specific<Wavefront> per_thread;
    Wavefront& w = per_thread.local();
    Ray batch_rays[kBatch];
    SurfaceHit batch_hits[kBatch];
    bool batch_found[kBatch];
    for (int first = 0; first < count; first += kBatch) {
        const int n = std::min(kBatch, count - first);
        w.paths.resize(static_cast<size_t>(n));
        w.live.clear();
        for (int i = 0; i < n; ++i) {
            w.paths[static_cast<size_t>(i)].start(rays[first + i], samples[first + i]);
            w.live.push_back(i);
        }
        counters.camera += static_cast<uint64_t>(n);
        for (bool camera_rays = true; !w.live.empty(); camera_rays = false) {
            const int live = static_cast<int>(w.live.size());
            for (int i = 0; i < live; ++i) batch_rays[i] = w.paths[size_t(w.live[size_t(i)])].ray;
            if (m_log) {
                std::vector<Ray>& kind = camera_rays ? m_log->camera : m_log->bounce;
                kind.insert(kind.end(), batch_rays, batch_rays + live);
            }
            const auto trace_start = std::chrono::steady_clock::now();
            m_accel.intersect_coherent(
                batch_rays, live, batch_hits, batch_found,
                camera_rays ? Accel::Coherence::Coherent : Accel::Coherence::Incoherent);
            (camera_rays ? counters.camera_trace_seconds : counters.bounce_trace_seconds) +=
                seconds_since(trace_start);
            w.lights.clear();
            w.light_path.clear();
            w.direct.assign(static_cast<size_t>(n), Vec3(0.0f));
            w.has_direct.assign(static_cast<size_t>(n), 0);
            int kept = 0;
            for (int i = 0; i < live; ++i) {
                const int k = w.live[size_t(i)];
                PathState& path = w.paths[size_t(k)];
                if (batch_found[i]) path.v.hit = batch_hits[i];
                if (!arrive(path, batch_found[i], counters)) continue;
                w.live[size_t(kept++)] = k;
                if (!path.v.bsdf.has_smooth_lobe()) continue;
                w.has_direct[size_t(k)] = 1;
                for (size_t index = 0; index < m_scene.lights.size(); ++index) {
                    LightSampleAt at;
                    if (!sample_light_at(path, index, at, counters)) continue;
                    w.lights.push_back(at);
                    w.light_path.push_back(k);
                }
            }
            w.live.resize(size_t(kept));
            // The shadow rays in calls of kBatch, in the order radiance() traces them; each
            // path's direct light sums its unoccluded samples in light order, as there.
            Ray shadows[kBatch];
            bool occluded[kBatch];
            for (size_t s = 0; s < w.lights.size(); s += kBatch) {
                const int m = static_cast<int>(std::min(w.lights.size() - s, size_t(kBatch)));
                for (int j = 0; j < m; ++j) shadows[j] = w.lights[s + size_t(j)].shadow;
                if (m_log) m_log->shadow.insert(m_log->shadow.end(), shadows, shadows + m);
                const auto shadow_start = std::chrono::steady_clock::now();
                m_accel.occluded_coherent(shadows, m, occluded, Accel::Coherence::Incoherent);
                counters.shadow_trace_seconds += seconds_since(shadow_start);
                for (int j = 0; j < m; ++j) {
                    if (occluded[j]) continue;
                    const int k = w.light_path[s + size_t(j)];
                    add_light(w.paths[size_t(k)], w.lights[s + size_t(j)], w.direct[size_t(k)]);
                }
            }
            kept = 0;
            for (const int k : w.live) {
                PathState& path = w.paths[size_t(k)];
                if (w.has_direct[size_t(k)]) path.radiance += path.throughput * w.direct[size_t(k)];
                if (scatter(path, counters)) w.live[size_t(kept++)] = k;
            }
            w.live.resize(size_t(kept));
        }
        for (int i = 0; i < n; ++i) out[first + i] = w.paths[size_t(i)].radiance;
    }
}

bool PathIntegrator::arrive(PathState& path, bool found, RayCounters& counters) const {
    const Fog& fog = m_scene.fog;
    Vertex& v = path.v;
    // The segment's medium: Beer–Lambert inside an absorbing object, else the fog.
    if (path.medium) {
        if (found) path.throughput *= beer_lambert(path.medium->absorption, v.hit.t);
    } else if (fog.enabled()) {
        if (!found) {
            path.radiance += path.throughput * fog.color;
            return false;
        }
        const float transmittance = std::exp(-fog.density * v.hit.t);
        path.radiance += path.throughput * fog.color * (1.0f - transmittance);
        path.throughput *= transmittance;
    }
    if (!found) {
        path.radiance += path.throughput * escaped(path.ray.direction, path.specular, path.bsdf_pdf,
                                                   path.previous_point);
        return false;
    }
    m_surfaces.interact(path.ray, v.hit, v.surface);
    const SurfaceCoefficients& material = v.surface.material();
    // An emitter is seen on its front, and on its back when two-sided (material.h).
    if (material.emits_toward(v.surface.entering)) {
        float weight = 1.0f;
        if (!path.specular && material.emitter_light >= 0) {
            if (m_settings.strategy == LightStrategy::Light) {
                weight = 0.0f;
            } else if (m_settings.strategy == LightStrategy::Mis) {
                const EmitterPoint at{v.hit.position, v.surface.facing_geometric,
                                      v.surface.base->emission};
                const float light_density =
                    light_pdf_at(m_scene.lights[material.emitter_light], path.previous_point,
                                 path.ray.direction, at);
                weight = power_heuristic(path.bsdf_pdf, light_density);
            }
        }
        path.radiance += path.throughput * material.emission * weight;
    }
    if (path.depth >= m_settings.max_depth) {
        ++counters.depth_cut;
        return false;
    }
    v.bsdf = material_bsdf(material);
    if (v.bsdf.size() == 0) return false;
    const Vec3 outside_normal = v.surface.entering ? v.surface.normal : -v.surface.normal;
    v.frame = LocalFrame::from_normal(outside_normal);
    v.wo = v.frame.to_local(v.surface.to_eye);
    const auto lights = static_cast<uint32_t>(m_scene.lights.size());
    const uint32_t stride = kFirstLightDimension + 2 * lights;
    path.dimension = kFirstIntegratorDimension + static_cast<uint32_t>(path.depth) * stride;
    return true;
}

bool PathIntegrator::scatter(PathState& path, RayCounters& counters) const {
    const Vertex& v = path.v;
    const SurfaceCoefficients& material = v.surface.material();
    ScatterSample s;
    if (!v.bsdf.sample(v.wo, path.sample.get2d(path.dimension + kBsdfDimension), s)) return false;
    const Vec3 direction = glm::normalize(v.frame.to_world(s.wi));
    Vec3 origin;
    if (!v.leave(direction, s.wi, origin)) return false;
    path.throughput *= s.value * (std::abs(s.wi.z) / s.pdf);
    const bool transmitted = s.wi.z * v.wo.z < 0.0f;
    if (transmitted) {
        ++counters.refraction;
        // A transmit colour below 1 tints what the dielectric lets through (seed 001's
        // weight; the diffuse transmission lobe has its own colour); entering an absorbing
        // object the ray travels inside it, leaving it travels in the fog.
        if (s.delta && material.transmissive()) path.throughput *= material.transmit;
        path.medium = v.surface.entering && v.surface.base->absorbing() ? v.surface.base : nullptr;
    } else {
        ++counters.reflection;
    }
    path.specular = s.delta;
    path.bsdf_pdf = s.pdf;
    path.previous_point = v.hit.position;
    // Russian roulette: continue with probability q = min(1, max throughput component) and
    // divide by q, so the expectation is unchanged.
    if (path.depth + 1 >= m_settings.roulette_depth) {
        const float q = std::min(1.0f, max_component(path.throughput));
        if (!(path.sample.get1d(path.dimension + kRouletteDimension) < q)) {
            ++counters.contribution_cut;
            return false;
        }
        path.throughput /= q;
    }
    path.ray.origin = origin;
    path.ray.direction = direction;
    path.ray.tnear = 0.0f;
    path.ray.tfar = std::numeric_limits<float>::infinity();
    ++path.depth;
    return true;
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

bool PathIntegrator::sample_light_at(const PathState& path, size_t index, LightSampleAt& at,
                                     RayCounters& counters) const {
    const Vertex& v = path.v;
    const Light& light = m_scene.lights[index];
    if (!light_is_delta(light) && m_settings.strategy == LightStrategy::Bsdf) return false;
    const glm::vec2 u =
        path.sample.get2d(path.dimension + kFirstLightDimension + 2 * static_cast<uint32_t>(index));
    if (!sample_light(light, v.hit.position, u, at.sample)) return false;
    at.light = index;
    at.wi = v.frame.to_local(at.sample.direction);
    at.f = v.bsdf.eval(v.wo, at.wi);
    if (at.f == Vec3(0.0f)) return false;
    Vec3 origin;
    if (!v.leave(at.sample.direction, at.wi, origin)) return false;
    ++counters.shadow;
    at.shadow = light_shadow_ray(v.hit.position, origin, at.sample);
    return true;
}

void PathIntegrator::add_light(const PathState& path, const LightSampleAt& at, Vec3& sum) const {
    const Vertex& v = path.v;
    const Light& light = m_scene.lights[at.light];
    const LightSample& ls = at.sample;
    const bool delta = light_is_delta(light);
    float weight = 1.0f;
    if (!delta && m_settings.strategy == LightStrategy::Mis) {
        weight = power_heuristic(ls.pdf, v.bsdf.pdf(v.wo, at.wi));
    }
    Vec3 incident = light_sample_radiance(ls, m_images) * (light_radiometric_scale(light) / ls.pdf);
    // The fog between (a directional light's, at no distance, is not dimmed): what a BSDF
    // ray that finds the same emitter carries too, so the two strategies agree.
    // The environment, infinitely far, is hidden by fog as a BSDF ray that escapes sees it.
    if (m_scene.fog.enabled()) {
        if (std::isfinite(ls.distance)) {
            incident *= std::exp(-m_scene.fog.density * ls.distance);
        } else if (!delta) {
            return;
        }
    }
    sum += at.f * incident * (std::abs(at.wi.z) * weight);
}

}  // namespace rayo
