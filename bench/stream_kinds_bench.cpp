// Each ray kind of the coherent path through rayo's Accel against raw Embree on the same rays.
// The rays are recorded from a render of an SPD scene that rayo generates (balls 3 by default,
// bench/lab/spd_scenes.h; RAYO_STREAM_SCENE=name:size picks another) at 512×512 (RAYO_STREAM_SIZE=N
// records an N×N frame instead: 2048 gives the rays of the 2048² comparison with POV-Ray): every
// stream call the integrator makes with stream_secondary (WhittedIntegrator::record_streams),
// replayed call by call with the same batch sizes and Embree context flags, on one thread: the
// rates are per CPU second of that thread, which other processes on a shared machine disturb far
// less than wall time.
//   Rayo/<kind>        Accel::intersect_coherent (with the hit record) / occluded_coherent
//   RayoSingle/<kind>  Accel::intersect / occluded ray by ray (the --single-rays path)
//   RawStream/<kind>   rtcIntersect1M / rtcOccluded1M on the same calls, nothing else
//   RawPacket/<kind>   rtcIntersect16 / rtcOccluded16 packets of the same rays (the alternative)
//   RawSingle/<kind>   rtcIntersect1 / rtcOccluded1 ray by ray (the single-ray ceiling)
// kind: 0 camera, 1 shadow from camera hits, 2 shadow from secondary hits, 3 reflected and
// refracted (RAYO_STREAM_COHERENT=1: all with the COHERENT flag, for comparison). Counters: Mrays/s
// (rays per CPU second).
// Kinds 4–6 are a diffuse-path frame: the rays the path integrator traces ray by ray
// (PathIntegrator::record_rays) on the built-in Cornell box (bench/lab/convergence_scene.h) at
// 256×256 and 4 spp (RAYO_PATH_SIZE=N, RAYO_PATH_SPP=S), one thread: 4 camera, 5 bounce (the
// rays the scattering functions sample), 6 shadow (next-event estimation). The path integrator
// traces single rays, so its own entry is RayoSingle; the stream entries group the rays 64 at a
// time in the order they were traced (consecutive vertices of a few paths: what a 64-path
// wavefront would hand Embree, no more coherent), to say whether streams would pay.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "apps/scene/renderer.h"
#include "apps/scene/sphere_method_choice.h"
#include "bench/bench_main.h"
#include "bench/lab/convergence_scene.h"
#include "bench/lab/spd_scenes.h"
#include "core/accel.h"
#include "core/camera.h"
#include "core/embree_ray.h"
#include "core/render.h"
#include "shading/integrators/path.h"
#include "shading/integrators/whitted.h"

namespace rayo {
namespace {

// A positive integer from the environment variable `name` (a multiple of `multiple`), or
// `fallback` when it is not set.
int environment_count(const char* name, int fallback, int multiple) {
    const char* env = std::getenv(name);
    const int n = env ? std::atoi(env) : fallback;
    if (n < multiple || n % multiple != 0) {
        std::fprintf(stderr, "%s=%s: expected a positive multiple of %d\n", name, env, multiple);
        std::exit(2);
    }
    return n;
}
// The recorded frame's width and height: 512, or RAYO_STREAM_SIZE (a multiple of 8).
int frame_size() {
    static const int size = environment_count("RAYO_STREAM_SIZE", 512, 8);
    return size;
}
const char* const kKindNames[] = {"camera",      "shadow-camera", "shadow-secondary", "secondary",
                                  "path-camera", "path-bounce",   "path-shadow"};
constexpr int kPathFirstKind = 4;

struct Recording {
    SceneDescription description;
    std::unique_ptr<Accel> accel;
    StreamLog
        log;  // kinds 0–3 (Whitted); kinds 4–6 (path) use log.camera, secondary, shadow_camera
    std::vector<size_t> offsets[7];  // first ray of each call, per kind

    const StreamLog::Calls& calls(int kind) const {
        const StreamLog::Calls* all[] = {
            &log.camera, &log.shadow_camera, &log.shadow_secondary, &log.secondary,
            &log.camera, &log.secondary,     &log.shadow_camera};
        return *all[kind];
    }
    void index_calls(int first_kind, int last_kind) {
        for (int kind = first_kind; kind <= last_kind; ++kind) {
            size_t offset = 0;
            for (const int n : calls(kind).sizes) {
                offsets[kind].push_back(offset);
                offset += static_cast<size_t>(n);
            }
        }
    }
    static bool closest_hit(int kind) { return kind == 0 || kind == 3 || kind == 4 || kind == 5; }
    // The renderer's flags; RAYO_STREAM_COHERENT=1 replays every kind with the COHERENT flag.
    static Accel::Coherence coherence(int kind) {
        static const bool all_coherent = std::getenv("RAYO_STREAM_COHERENT") != nullptr;
        return kind <= 1 || kind == kPathFirstKind || all_coherent ? Accel::Coherence::Coherent
                                                                   : Accel::Coherence::Incoherent;
    }
};

// Renders the scene once, one thread, through the coherent path with a stream log: the camera
// rays of each 8×8 block (the renderer's 64-ray batches) as the renderer makes them at 1 spp.
const Recording& recording() {
    static const Recording r = [] {
        Recording rec;
        std::string name = "balls";
        int size = 3;
        if (const char* env = std::getenv("RAYO_STREAM_SCENE")) {
            const std::string spec = env;
            const size_t colon = spec.find(':');
            name = spec.substr(0, colon);
            if (colon != std::string::npos) size = std::stoi(spec.substr(colon + 1));
        }
        rec.description = spd_scene(name, size);
        const int frame = frame_size();
        rec.description.scene.camera.width = frame;
        rec.description.scene.camera.height = frame;
        const Camera camera = Camera::create(rec.description.scene.camera);
        const SphereChoice spheres = choose_sphere_method(rec.description, camera);
        AccelOptions options;
        options.spheres = spheres.spheres;
        options.sphere_math = spheres.math;
        rec.accel = std::make_unique<Accel>(rec.description.scene, options);
        WhittedSettings settings = rec.description.settings.whitted();
        settings.stream_secondary = true;  // the wavefront through every depth
        WhittedIntegrator integrator(*rec.accel, rec.description.shading, settings);
        integrator.record_streams(&rec.log);
        RayCounters counters;
        Ray rays[64];
        PixelSample samples[64];
        Vec3 radiance[64];
        for (int by = 0; by < frame; by += 8) {
            for (int bx = 0; bx < frame; bx += 8) {
                int n = 0;
                for (int y = by; y < by + 8; ++y) {
                    for (int x = bx; x < bx + 8; ++x)
                        n += pixel_ray(camera, x, y, 0, 1, rays[n], samples[n]);
                }
                integrator.radiance_coherent(rays, samples, n, radiance, counters);
            }
        }
        rec.index_calls(0, kPathFirstKind - 1);
        return rec;
    }();
    return r;
}

// The diffuse-path frame (kinds 4–6): the path integrator's rays on the Cornell box, one thread,
// in calls of 64 in the order traced.
const Recording& path_recording() {
    static const Recording r = [] {
        Recording rec;
        rec.description = convergence_cornell_box();
        const int frame = environment_count("RAYO_PATH_SIZE", 256, 8);
        const auto spp = static_cast<uint32_t>(environment_count("RAYO_PATH_SPP", 4, 1));
        rec.description.scene.camera.width = frame;
        rec.description.scene.camera.height = frame;
        const Camera camera = Camera::create(rec.description.scene.camera);
        rec.accel = std::make_unique<Accel>(rec.description.scene, AccelOptions{});
        const IntegratorContext context{*rec.accel, rec.description.shading};
        PathIntegrator integrator(context, PathSettings{});
        PathRayLog log;
        integrator.record_rays(&log);
        RayCounters counters;
        for (int y = 0; y < frame; ++y) {
            for (int x = 0; x < frame; ++x) {
                for (uint32_t s = 0; s < spp; ++s) {
                    Ray ray;
                    PixelSample sample;
                    if (pixel_ray(camera, x, y, s, spp, ray, sample)) {
                        integrator.radiance(ray, sample, counters);
                    }
                }
            }
        }
        const auto to_calls = [](const std::vector<Ray>& rays, StreamLog::Calls& calls) {
            for (size_t first = 0; first < rays.size(); first += Accel::kCoherentBatch) {
                const size_t n =
                    std::min(rays.size() - first, static_cast<size_t>(Accel::kCoherentBatch));
                calls.add(rays.data() + first, static_cast<int>(n));
            }
        };
        to_calls(log.camera, rec.log.camera);
        to_calls(log.bounce, rec.log.secondary);
        to_calls(log.shadow, rec.log.shadow_camera);
        rec.index_calls(kPathFirstKind, kPathFirstKind + 2);
        return rec;
    }();
    return r;
}

const Recording& recording(int kind) {
    return kind < kPathFirstKind ? recording() : path_recording();
}

// Replays every recorded call of `kind` through `trace_call(rays, n)` (which returns how many
// rays hit or are occluded), on one thread.
template <typename TraceCall>
void replay(benchmark::State& state, TraceCall trace_call) {
    const int kind = static_cast<int>(state.range(0));
    const Recording& rec = recording(kind);
    const StreamLog::Calls& calls = rec.calls(kind);
    size_t hits = 0;
    for (auto _ : state) {
        hits = 0;
        for (size_t c = 0; c < calls.sizes.size(); ++c) {
            hits += trace_call(calls.rays.data() + rec.offsets[kind][c], calls.sizes[c], kind);
        }
    }
    state.SetLabel(kKindNames[kind]);
    state.counters["Mrays/s"] =
        benchmark::Counter(static_cast<double>(calls.rays.size()) * state.iterations() / 1e6,
                           benchmark::Counter::kIsRate);
    state.counters["rays"] = static_cast<double>(calls.rays.size());
    state.counters["hit%"] = 100.0 * static_cast<double>(hits) / calls.rays.size();
}

void Rayo(benchmark::State& state) {
    const Accel& accel = *recording(static_cast<int>(state.range(0))).accel;
    replay(state, [&](const Ray* rays, int n, int kind) {
        size_t count = 0;
        bool result[Accel::kCoherentBatch];
        if (Recording::closest_hit(kind)) {
            SurfaceHit hits[Accel::kCoherentBatch];
            accel.intersect_coherent(rays, n, hits, result, Recording::coherence(kind));
        } else {
            accel.occluded_coherent(rays, n, result, Recording::coherence(kind));
        }
        for (int i = 0; i < n; ++i) count += result[i];
        return count;
    });
}

void RayoSingle(benchmark::State& state) {
    const Accel& accel = *recording(static_cast<int>(state.range(0))).accel;
    replay(state, [&](const Ray* rays, int n, int kind) {
        size_t count = 0;
        for (int i = 0; i < n; ++i) {
            SurfaceHit hit;
            count += Recording::closest_hit(kind) ? accel.intersect(rays[i], hit)
                                                  : accel.occluded(rays[i]);
        }
        return count;
    });
}

void RawStream(benchmark::State& state) {
    const RTCScene scene = recording(static_cast<int>(state.range(0))).accel->rtc_scene();
    replay(state, [&](const Ray* rays, int n, int kind) {
        RTCIntersectContext context = stream_context(Recording::coherence(kind));
        size_t count = 0;
        if (Recording::closest_hit(kind)) {
            RTCRayHit batch[Accel::kCoherentBatch];
            for (int i = 0; i < n; ++i) batch[i] = make_rtc_rayhit(rays[i]);
            rtcIntersect1M(scene, &context, batch, static_cast<unsigned>(n), sizeof(RTCRayHit));
            for (int i = 0; i < n; ++i) count += batch[i].hit.geomID != RTC_INVALID_GEOMETRY_ID;
        } else {
            RTCRay batch[Accel::kCoherentBatch];
            for (int i = 0; i < n; ++i) batch[i] = make_rtc_ray(rays[i]);
            rtcOccluded1M(scene, &context, batch, static_cast<unsigned>(n), sizeof(RTCRay));
            for (int i = 0; i < n; ++i) count += batch[i].tfar < 0.0f;
        }
        return count;
    });
}

// Packets of 16 in the call's order (SOA), inactive lanes masked off.
void RawPacket(benchmark::State& state) {
    const RTCScene scene = recording(static_cast<int>(state.range(0))).accel->rtc_scene();
    replay(state, [&](const Ray* rays, int n, int kind) {
        RTCIntersectContext context = stream_context(Recording::coherence(kind));
        size_t count = 0;
        for (int first = 0; first < n; first += 16) {
            alignas(64) int valid[16];
            alignas(64) RTCRayHit16 packet;
            for (int i = 0; i < 16; ++i) {
                const bool active = first + i < n;
                valid[i] = active ? -1 : 0;
                const Ray& r = rays[active ? first + i : first];
                packet.ray.org_x[i] = r.origin.x;
                packet.ray.org_y[i] = r.origin.y;
                packet.ray.org_z[i] = r.origin.z;
                packet.ray.dir_x[i] = r.direction.x;
                packet.ray.dir_y[i] = r.direction.y;
                packet.ray.dir_z[i] = r.direction.z;
                packet.ray.tnear[i] = r.tnear;
                packet.ray.tfar[i] = r.tfar;
                packet.ray.time[i] = 0.0f;
                packet.ray.mask[i] = 0xFFFFFFFFu;
                packet.ray.id[i] = 0;
                packet.ray.flags[i] = 0;
                packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
                packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
            }
            const int lanes = std::min(16, n - first);
            if (Recording::closest_hit(kind)) {
                rtcIntersect16(valid, scene, &context, &packet);
                for (int i = 0; i < lanes; ++i) {
                    count += packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
                }
            } else {
                rtcOccluded16(valid, scene, &context, &packet.ray);
                for (int i = 0; i < lanes; ++i) count += packet.ray.tfar[i] < 0.0f;
            }
        }
        return count;
    });
}

void RawSingle(benchmark::State& state) {
    const RTCScene scene = recording(static_cast<int>(state.range(0))).accel->rtc_scene();
    replay(state, [&](const Ray* rays, int n, int kind) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        size_t count = 0;
        for (int i = 0; i < n; ++i) {
            if (Recording::closest_hit(kind)) {
                RTCRayHit rh = make_rtc_rayhit(rays[i]);
                rtcIntersect1(scene, &context, &rh);
                count += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            } else {
                RTCRay r = make_rtc_ray(rays[i]);
                rtcOccluded1(scene, &context, &r);
                count += r.tfar < 0.0f;
            }
        }
        return count;
    });
}

void kinds(benchmark::internal::Benchmark* b) {
    b->DenseRange(0, 6)->Unit(benchmark::kMillisecond);
}
BENCHMARK(Rayo)->Apply(kinds);
BENCHMARK(RayoSingle)->Apply(kinds);
BENCHMARK(RawStream)->Apply(kinds);
BENCHMARK(RawPacket)->Apply(kinds);
BENCHMARK(RawSingle)->Apply(kinds);

}  // namespace
}  // namespace rayo

RAYO_BENCHMARK_MAIN()
