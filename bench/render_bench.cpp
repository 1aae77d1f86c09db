// Throughput of rayo's intersection and render paths on a sphereflake it generates itself
// (SPD "balls" layout, depth 4 = 7381 spheres + a floor), 512×512 camera rays, one per pixel
// centre. Counters: Mrays/s (rays per wall-clock second, all threads).
//   CameraRays/<math>   Accel::intersect (Embree user geometry + our quadratic + hit record)
//   CameraRaysCoherent  Accel::intersect_coherent on 8×8 tiles (the renderer's camera path)
//   RawEmbreeUserStream rtcIntersect1M on the same tiles, COHERENT flag, no hit record
//   RawEmbreeUser       rtcIntersect1 on the same Embree scene, no hit record (our ceiling)
//   RawEmbreePoint      rtcIntersect1 on Embree's built-in RTC_GEOMETRY_TYPE_SPHERE_POINT
//   FullRender          the whole Whitted render (shadow + reflection rays included)
#include <benchmark/benchmark.h>
#include <tbb/blocked_range2d.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <vector>

#include "apps/scene/renderer.h"
#include "apps/scene/sphereflake.h"
#include "bench/bench_main.h"
#include "core/accel.h"
#include "core/camera.h"
#include "core/embree_device.h"

namespace rayo {
namespace {

constexpr int kDepth = 4;
constexpr int kSize = 512;

const SceneDescription& flake() {
    static const SceneDescription d = make_sphereflake(kDepth, kSize, kSize);
    return d;
}

std::vector<Ray> camera_rays() {
    const Camera camera = Camera::create(flake().scene.camera);
    std::vector<Ray> rays;
    rays.reserve(static_cast<size_t>(kSize) * kSize);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) rays.push_back(camera.generate_ray(float(x), float(y)));
    }
    return rays;
}

template <typename TraceOne>
void trace_all(benchmark::State& state, const std::vector<Ray>& rays, TraceOne trace_one) {
    size_t hits = 0;
    for (auto _ : state) {
        std::atomic<size_t> frame_hits{0};
        tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 4096),
                          [&](const tbb::blocked_range<size_t>& r) {
                              size_t local = 0;
                              for (size_t i = r.begin(); i < r.end(); ++i)
                                  local += trace_one(rays[i]);
                              frame_hits += local;
                          });
        hits = frame_hits;
    }
    state.counters["Mrays/s"] = benchmark::Counter(
        static_cast<double>(rays.size()) * state.iterations() / 1e6, benchmark::Counter::kIsRate);
    state.counters["hit%"] = 100.0 * hits / rays.size();
}

RTCRayHit to_rayhit(const Ray& ray) {
    RTCRayHit rh;
    rh.ray.org_x = ray.origin.x;
    rh.ray.org_y = ray.origin.y;
    rh.ray.org_z = ray.origin.z;
    rh.ray.dir_x = ray.direction.x;
    rh.ray.dir_y = ray.direction.y;
    rh.ray.dir_z = ray.direction.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = ray.tfar;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.flags = 0;
    rh.ray.time = 0.0f;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

void CameraRays(benchmark::State& state) {
    AccelOptions options;
    options.sphere_math = state.range(0) == 0 ? SphereMath::Stable : SphereMath::Seed;
    state.SetLabel(state.range(0) == 0 ? "stable" : "seed");
    const Accel accel(flake().scene, options);
    const std::vector<Ray> rays = camera_rays();
    trace_all(state, rays, [&](const Ray& ray) {
        SurfaceHit hit;
        return accel.intersect(ray, hit) ? 1 : 0;
    });
}
BENCHMARK(CameraRays)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// Traces the camera rays in 8×8 tiles (the renderer's batches): `trace_tile(rays, n)` returns
// how many of the n rays hit.
template <typename TraceTile>
void trace_tiles(benchmark::State& state, const std::vector<Ray>& rays, TraceTile trace_tile) {
    size_t hits = 0;
    for (auto _ : state) {
        std::atomic<size_t> frame_hits{0};
        tbb::parallel_for(
            tbb::blocked_range2d<int>(0, kSize, 8, 0, kSize, 8),
            [&](const tbb::blocked_range2d<int>& tile) {
                Ray batch[64];
                int n = 0;
                for (int y = tile.rows().begin(); y < tile.rows().end(); ++y) {
                    for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) {
                        batch[n++] = rays[size_t(y) * kSize + x];
                    }
                }
                frame_hits += trace_tile(batch, n);
            },
            tbb::simple_partitioner());
        hits = frame_hits;
    }
    state.counters["Mrays/s"] = benchmark::Counter(
        static_cast<double>(rays.size()) * state.iterations() / 1e6, benchmark::Counter::kIsRate);
    state.counters["hit%"] = 100.0 * hits / rays.size();
}

// Accel::intersect_coherent over 8×8 tiles: the renderer's camera-ray path (streams + records).
void CameraRaysCoherent(benchmark::State& state) {
    const Accel accel(flake().scene);
    trace_tiles(state, camera_rays(), [&](const Ray* batch, int n) {
        SurfaceHit records[64];
        bool found[64];
        accel.intersect_coherent(batch, n, records, found);
        size_t hits = 0;
        for (int i = 0; i < n; ++i) hits += found[i];
        return hits;
    });
}
BENCHMARK(CameraRaysCoherent)->Unit(benchmark::kMillisecond)->UseRealTime();

void RawEmbreeUser(benchmark::State& state) {
    const Accel accel(flake().scene);
    const std::vector<Ray> rays = camera_rays();
    trace_all(state, rays, [&](const Ray& ray) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh = to_rayhit(ray);
        rtcIntersect1(accel.rtc_scene(), &context, &rh);
        return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? 1 : 0;
    });
}
BENCHMARK(RawEmbreeUser)->Unit(benchmark::kMillisecond)->UseRealTime();

// rtcIntersect1M over 8×8 tiles of camera rays with the COHERENT context flag: Embree
// traverses them as packets and calls the user-geometry callback with N lanes.
void RawEmbreeUserStream(benchmark::State& state) {
    const Accel accel(flake().scene);
    trace_tiles(state, camera_rays(), [&](const Ray* rays, int n) {
        RTCRayHit batch[64];
        for (int i = 0; i < n; ++i) batch[i] = to_rayhit(rays[i]);
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        rtcIntersect1M(accel.rtc_scene(), &context, batch, n, sizeof(RTCRayHit));
        size_t hits = 0;
        for (int i = 0; i < n; ++i) hits += batch[i].hit.geomID != RTC_INVALID_GEOMETRY_ID;
        return hits;
    });
}
BENCHMARK(RawEmbreeUserStream)->Unit(benchmark::kMillisecond)->UseRealTime();

void RawEmbreePoint(benchmark::State& state) {
    const Scene& scene = flake().scene;
    RTCDevice device = rtcNewDevice(kEmbreeDeviceConfig);
    RTCScene rtc = rtcNewScene(device);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* points = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT4, 4 * sizeof(float),
                                                               scene.shapes.of<Sphere>().size()));
    for (size_t i = 0; i < scene.shapes.of<Sphere>().size(); ++i) {
        points[4 * i + 0] = scene.shapes.of<Sphere>()[i].center.x;
        points[4 * i + 1] = scene.shapes.of<Sphere>()[i].center.y;
        points[4 * i + 2] = scene.shapes.of<Sphere>()[i].center.z;
        points[4 * i + 3] = scene.shapes.of<Sphere>()[i].radius;
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(rtc, g);
    rtcReleaseGeometry(g);
    // The same floor as the flake scene, so both scenes see the same rays hit the same things.
    const TriangleMesh& floor = scene.meshes.front();
    RTCGeometry tris = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(tris, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                          floor.positions.size()));
    for (size_t i = 0; i < floor.positions.size(); ++i) {
        v[3 * i + 0] = floor.positions[i].x;
        v[3 * i + 1] = floor.positions[i].y;
        v[3 * i + 2] = floor.positions[i].z;
    }
    auto* idx = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(tris, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), floor.triangles.size()));
    for (size_t i = 0; i < floor.triangles.size(); ++i) {
        for (int k = 0; k < 3; ++k) idx[3 * i + k] = floor.triangles[i][k];
    }
    rtcCommitGeometry(tris);
    rtcAttachGeometry(rtc, tris);
    rtcReleaseGeometry(tris);
    rtcCommitScene(rtc);
    const std::vector<Ray> rays = camera_rays();
    trace_all(state, rays, [&](const Ray& ray) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh = to_rayhit(ray);
        rtcIntersect1(rtc, &context, &rh);
        return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? 1 : 0;
    });
    rtcReleaseScene(rtc);
    rtcReleaseDevice(device);
}
BENCHMARK(RawEmbreePoint)->Unit(benchmark::kMillisecond)->UseRealTime();

void FullRender(benchmark::State& state) {
    uint64_t rays = 0;
    for (auto _ : state) {
        const RenderResult r = render_scene(flake(), 0, false);
        rays += r.counters.total_rays();
    }
    state.counters["Mrays/s"] =
        benchmark::Counter(static_cast<double>(rays) / 1e6, benchmark::Counter::kIsRate);
    state.counters["rays/frame"] = static_cast<double>(rays) / state.iterations();
}
BENCHMARK(FullRender)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace rayo

RAYO_BENCHMARK_MAIN()
