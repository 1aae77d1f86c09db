// Nanoseconds per evaluation of each procedural map (seed 003 ch. 3), one thread: the noise
// primitives, Worley cells per metric, and every named texture's colour (texture.h). Points walk
// a fixed pseudo-random sequence over a 100-unit cube so that caches and branch predictors see
// realistic, non-repeating inputs. Counter "ns/eval" is the wall time per evaluation.
#include <benchmark/benchmark.h>

#include <vector>

#include "bench/bench_main.h"
#include "shading/cellular.h"
#include "shading/noise.h"
#include "shading/texture.h"

namespace rayo {
namespace {

const std::vector<Vec3>& points() {
    static const std::vector<Vec3> pts = [] {
        std::vector<Vec3> v;
        for (uint32_t i = 0; i < 4096; ++i) {
            const uint32_t h = hash_u32(i * 2654435761u + 17u);
            v.emplace_back(unit_float(h) * 100.0f - 50.0f,
                           unit_float(hash_u32(h + 1)) * 100.0f - 50.0f,
                           unit_float(hash_u32(h + 2)) * 100.0f - 50.0f);
        }
        return v;
    }();
    return pts;
}

template <class F>
void run(benchmark::State& state, F f) {
    const std::vector<Vec3>& pts = points();
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(f(pts[i]));
        i = (i + 1) & 4095u;
    }
    // kIsRate | kInvert: seconds per evaluation; reported in ns by the 1e9 factor.
    state.counters["ns/eval"] =
        benchmark::Counter(static_cast<double>(state.iterations()) / 1e9,
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_ValueNoise2D(benchmark::State& s) {
    run(s, [](const Vec3& p) { return value_noise_2d(p.x, p.y, 1); });
}
void BM_SmoothedValueNoise2D(benchmark::State& s) {
    run(s, [](const Vec3& p) { return smoothed_value_noise_2d(p.x, p.y, 1); });
}
void BM_ValueNoise3D(benchmark::State& s) {
    run(s, [](const Vec3& p) { return value_noise_3d(p, 1); });
}
void BM_GradientNoise3D(benchmark::State& s) {
    run(s, [](const Vec3& p) { return gradient_noise_3d(p, 1); });
}
void BM_Fbm6Gradient(benchmark::State& s) {
    run(s, [](const Vec3& p) { return fbm(p, {}, 1); });
}
void BM_Fbm6Value(benchmark::State& s) {
    run(s, [](const Vec3& p) { return fbm(p, {}, 1, NoiseBasis::Value); });
}
void BM_Turbulence6(benchmark::State& s) {
    run(s, [](const Vec3& p) { return turbulence(p, {}, 1); });
}
void BM_Cellular2D(benchmark::State& s) {
    run(s, [](const Vec3& p) { return cellular_2d(p.x, p.y, 1).f3; });
}
void BM_Cellular3D(benchmark::State& s) {
    const auto metric = static_cast<DistanceMetric>(s.range(0));
    run(s, [metric](const Vec3& p) { return cellular_3d(p, 1, metric).f3; });
}
void BM_TextureColor(benchmark::State& s, const char* kind) {
    const Texture t = make_texture(kind);
    run(s, [&t](const Vec3& p) { return t.color(p); });
}
void BM_TextureGradient(benchmark::State& s, const char* kind) {
    const Texture t = make_texture(kind);
    run(s, [&t](const Vec3& p) { return t.gradient(p); });
}

BENCHMARK(BM_ValueNoise2D);
BENCHMARK(BM_SmoothedValueNoise2D);
BENCHMARK(BM_ValueNoise3D);
BENCHMARK(BM_GradientNoise3D);
BENCHMARK(BM_Fbm6Gradient);
BENCHMARK(BM_Fbm6Value);
BENCHMARK(BM_Turbulence6);
BENCHMARK(BM_Cellular2D);
BENCHMARK(BM_Cellular3D)->Arg(0)->Arg(1)->Arg(2)->ArgName("metric");
BENCHMARK_CAPTURE(BM_TextureColor, constant, "constant");
BENCHMARK_CAPTURE(BM_TextureColor, value, "value");
BENCHMARK_CAPTURE(BM_TextureColor, perlin, "perlin");
BENCHMARK_CAPTURE(BM_TextureColor, turbulence, "turbulence");
BENCHMARK_CAPTURE(BM_TextureColor, cellular, "cellular");
BENCHMARK_CAPTURE(BM_TextureColor, marble, "marble");
BENCHMARK_CAPTURE(BM_TextureColor, warped, "warped");
BENCHMARK_CAPTURE(BM_TextureColor, pool_bottom, "pool-bottom");
BENCHMARK_CAPTURE(BM_TextureGradient, perlin, "perlin");

}  // namespace
}  // namespace rayo

RAYO_BENCHMARK_MAIN()
