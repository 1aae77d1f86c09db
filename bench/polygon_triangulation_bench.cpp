// Time of triangulate_polygon (core/shapes/polygon_triangulation.h) on concave outlines of growing
// size: gears like the SPD's (4 vertices per tooth, half of them reflex) and combs (teeth on a
// bar), and on a convex polygon (the fan). Ear clipping costs O(N·R) for N vertices, R reflex.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "bench/bench_main.h"
#include "core/shapes/polygon_triangulation.h"

namespace rayo {
namespace {

std::vector<Vec3> gear(int teeth) {
    std::vector<Vec3> v;
    const double step = 2.0 * M_PI / teeth;
    const double corners[4][2] = {{0.0, 0.9}, {0.15, 1.0}, {0.35, 1.0}, {0.5, 0.9}};
    for (int t = 0; t < teeth; ++t) {
        for (const auto& c : corners) {
            const double a = t * step + c[0] * step;
            v.emplace_back(float(c[1] * std::cos(a)), float(c[1] * std::sin(a)), 0.0f);
        }
    }
    return v;
}

std::vector<Vec3> comb(int teeth) {
    std::vector<Vec3> v = {Vec3(3.0f * float(teeth), 0.0f, 0.0f)};
    for (int t = teeth - 1; t >= 0; --t) {
        const float x = 3.0f * float(t);
        for (const float dx : {2.0f, 1.0f}) v.emplace_back(x + dx, 4.0f, 0.0f);
        for (const float dx : {1.0f, 0.0f}) v.emplace_back(x + dx, 1.0f, 0.0f);
    }
    v.emplace_back(0.0f, 0.0f, 0.0f);
    return v;
}

std::vector<Vec3> circle(int n) {
    std::vector<Vec3> v;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        v.emplace_back(float(std::cos(a)), float(std::sin(a)), 0.0f);
    }
    return v;
}

template <class Make>
void run(benchmark::State& state, Make make) {
    const std::vector<Vec3> polygon = make(static_cast<int>(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(triangulate_polygon(polygon));
    state.counters["vertices"] = double(polygon.size());
}

void BM_Gear(benchmark::State& state) {
    run(state, gear);
}
void BM_Comb(benchmark::State& state) {
    run(state, comb);
}
void BM_ConvexCircle(benchmark::State& state) {
    run(state, circle);
}

BENCHMARK(BM_Gear)->Arg(36)->Arg(360)->Arg(2500)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Comb)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ConvexCircle)->Arg(144)->Arg(40000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rayo

RAYO_BENCHMARK_MAIN();
