// Throughput of every sphere method (docs/sphere-methods.md): Mrays/s per method × sphere count (10
// … 10⁶) × ray kind, plus BVH build time and Embree bytes per primitive.
//   Kinds: Camera    256×256 pinhole rays in 8×8 coherent batches (Accel::intersect_coherent)
//          Random    incoherent rays, random origins in the box and random directions
//          Occlusion random segments between two points of the box (Accel::occluded)
//   Counters: Mrays/s (wall clock, one thread: the scaling with threads is render_bench's),
//          hit% (same for every method up to silhouette differences), build_ms, bytes/prim.
// Spheres: `count` random spheres in a cube of side 100, radius chosen so that about a third of
// random rays hit something; the same spheres (seeded) for every method.
// Limits: bruteforce up to 10⁴ spheres (it tests every sphere), mesh:2 up to 10⁵ (320 triangles
// per sphere).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <vector>

#include "bench/bench_main.h"
#include "core/accel.h"
#include "core/camera.h"

namespace rayo {
namespace {

constexpr float kBox = 100.0f;

Scene make_scene(int count) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> position(0.0f, kBox);
    // Volume fraction ~ count·(4/3)πr³/L³; a ray of length ~L crosses ~ count·πr²/L² spheres.
    const float radius = 0.25f * kBox / std::cbrt(static_cast<float>(count)) * 0.5f;
    Scene scene;
    scene.shapes.of<Sphere>().reserve(count);
    for (int i = 0; i < count; ++i) {
        scene.shapes.of<Sphere>().push_back(
            {Vec3(position(rng), position(rng), position(rng)), radius, 0});
    }
    return scene;
}

struct Fixture {
    Scene scene;
    std::unique_ptr<Accel> accel;
    double build_ms = 0.0;
};

const char* const kMethods[] = {"user", "bruteforce", "embree-point", "mesh:2"};

Fixture& fixture(int count, int method) {
    static std::map<std::pair<int, int>, std::unique_ptr<Fixture>> cache;
    auto& slot = cache[{count, method}];
    if (!slot) {
        slot = std::make_unique<Fixture>();
        slot->scene = make_scene(count);
        AccelOptions options;
        options.spheres = *parse_sphere_method(kMethods[method]);
        const auto start = std::chrono::steady_clock::now();
        slot->accel = std::make_unique<Accel>(slot->scene, options);
        slot->build_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
    }
    return *slot;
}

std::vector<Ray> camera_rays() {
    CameraDesc desc;
    desc.eye = Vec3(-0.6f * kBox, 0.5f * kBox, 0.5f * kBox);
    desc.look_at = Vec3(0.5f * kBox);
    desc.up = Vec3(0, 0, 1);
    desc.vfov_degrees = 60.0f;
    desc.width = desc.height = 256;
    const Camera camera = Camera::create(desc);
    std::vector<Ray> rays;
    // 8×8 tiles in row-major order, as the renderer batches them.
    for (int ty = 0; ty < 256; ty += 8)
        for (int tx = 0; tx < 256; tx += 8)
            for (int y = ty; y < ty + 8; ++y)
                for (int x = tx; x < tx + 8; ++x) rays.push_back(camera.generate_ray(x, y));
    return rays;
}

std::vector<Ray> random_rays(bool segments) {
    std::mt19937 rng(777);
    std::uniform_real_distribution<float> position(0.0f, kBox);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    std::vector<Ray> rays(65536);
    for (Ray& ray : rays) {
        ray.origin = Vec3(position(rng), position(rng), position(rng));
        if (segments) {
            const Vec3 to = Vec3(position(rng), position(rng), position(rng));
            ray.direction = glm::normalize(to - ray.origin);
            ray.tfar = glm::length(to - ray.origin);
        } else {
            ray.direction = glm::normalize(Vec3(normal(rng), normal(rng), normal(rng)));
        }
    }
    return rays;
}

enum Kind { kCamera, kRandom, kOcclusion };

void SphereMethods(benchmark::State& state) {
    const int count = static_cast<int>(state.range(0));
    const int method = static_cast<int>(state.range(1));
    const auto kind = static_cast<Kind>(state.range(2));
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    Fixture& f = fixture(count, method);
    static const std::vector<Ray> camera = camera_rays(), random = random_rays(false),
                                  segments = random_rays(true);
    const std::vector<Ray>& rays = kind == kCamera ? camera : kind == kRandom ? random : segments;
    std::vector<SurfaceHit> hits(Accel::kCoherentBatch);
    std::unique_ptr<bool[]> found(new bool[Accel::kCoherentBatch]);
    size_t hit_count = 0;
    for (auto _ : state) {
        hit_count = 0;
        if (kind == kCamera) {
            for (size_t first = 0; first < rays.size(); first += Accel::kCoherentBatch) {
                f.accel->intersect_coherent(&rays[first], Accel::kCoherentBatch, hits.data(),
                                            found.get());
                for (int i = 0; i < Accel::kCoherentBatch; ++i) hit_count += found[i];
            }
        } else if (kind == kRandom) {
            SurfaceHit hit;
            for (const Ray& ray : rays) hit_count += f.accel->intersect(ray, hit);
        } else {
            for (const Ray& ray : rays) hit_count += f.accel->occluded(ray);
        }
    }
    state.counters["Mrays/s"] = benchmark::Counter(
        static_cast<double>(rays.size()) * state.iterations() / 1e6, benchmark::Counter::kIsRate);
    state.counters["hit%"] = 100.0 * hit_count / rays.size();
    state.counters["build_ms"] = f.build_ms;
    state.counters["bytes/prim"] = static_cast<double>(f.accel->embree_bytes()) / count;
    state.SetLabel(std::string(kMethods[method]) + " " +
                   (kind == kCamera   ? "camera"
                    : kind == kRandom ? "random"
                                      : "occlusion"));
}

void register_all(benchmark::internal::Benchmark* b) {
    for (int count : {10, 100, 1000, 10000, 100000, 1000000}) {
        for (int method = 0; method < 4; ++method) {
            if (method == 1 && count > 10000) continue;   // bruteforce: O(count) per ray
            if (method == 3 && count > 100000) continue;  // mesh:2: 320 triangles per sphere
            for (int kind : {kCamera, kRandom, kOcclusion}) b->Args({count, method, kind});
        }
    }
}
BENCHMARK(SphereMethods)->Apply(register_all)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace rayo

RAYO_BENCHMARK_MAIN()
