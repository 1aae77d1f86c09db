// Concave polygons in two forms (issue 11 item 6; docs/nff.md "Point in polygon against
// triangles"): ear-clipped into Embree triangles (core/shapes/polygon_triangulation.h, what rayo
// renders) against one Embree user-geometry primitive per polygon running the plane hit and a
// point-in-polygon test (core/shapes/planar_polygon.h, seed 004's parity rule). The scene is a
// square grid of flat gears like the SPD's (4 vertices per tooth); rays fall obliquely on it.
// Reported per form: build time, Embree's bytes plus the geometry's own, and rays per second.
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "bench/bench_main.h"
#include "core/embree_device.h"
#include "core/shapes/planar_polygon.h"
#include "core/shapes/polygon_triangulation.h"
#include "core/user_geometry.h"

namespace rayo {
namespace {

constexpr int kGearsPerSide = 16;  // 256 gears
constexpr float kSpacing = 2.2f;
constexpr int kRaysPerSide = 512;

std::vector<Vec3> gear(int teeth, Vec3 center, double phase) {
    std::vector<Vec3> v;
    const double step = 2.0 * M_PI / teeth;
    const double corners[4][2] = {{0.0, 0.8}, {0.15, 1.0}, {0.35, 1.0}, {0.5, 0.8}};
    for (int t = 0; t < teeth; ++t) {
        for (const auto& c : corners) {
            const double a = phase + t * step + c[0] * step;
            v.push_back(center + Vec3(float(c[1] * std::cos(a)), float(c[1] * std::sin(a)), 0.0f));
        }
    }
    return v;
}

std::vector<std::vector<Vec3>> gear_grid(int teeth) {
    std::vector<std::vector<Vec3>> gears;
    for (int i = 0; i < kGearsPerSide; ++i) {
        for (int j = 0; j < kGearsPerSide; ++j) {
            gears.push_back(gear(teeth, Vec3(i * kSpacing, j * kSpacing, 0.0f), 0.1 * (i + j)));
        }
    }
    return gears;
}

// A built scene of either form and what it holds.
struct PolygonScene {
    RTCScene scene = nullptr;
    double build_seconds = 0.0;
    double bytes = 0.0;  // Embree's (BVH and copied buffers) plus the geometry's own
    std::vector<PlanarPolygon> polygons;
    UserGeometryData<PlanarPolygon> data;
    ~PolygonScene() {
        if (scene) rtcReleaseScene(scene);
    }
};

// Makes `geometry` the one geometry of out.scene, commits it and records the build time since
// `start` and the bytes Embree gained since `before`.
void commit_alone(RTCGeometry geometry, std::chrono::steady_clock::time_point start,
                  long long before, PolygonScene& out) {
    out.scene = rtcNewScene(embree_device());
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(out.scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(out.scene);
    out.build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.bytes = double(embree_bytes_in_use() - before);
}

void build_triangles(const std::vector<std::vector<Vec3>>& gears, PolygonScene& out) {
    const long long before = embree_bytes_in_use();
    const auto start = std::chrono::steady_clock::now();
    std::vector<Vec3> positions;
    std::vector<PolygonTriangle> triangles;
    for (const std::vector<Vec3>& outline : gears) {
        const auto base = static_cast<uint32_t>(positions.size());
        for (PolygonTriangle t : triangulate_polygon(outline)) {
            triangles.push_back({base + t[0], base + t[1], base + t[2]});
        }
        positions.insert(positions.end(), outline.begin(), outline.end());
    }
    RTCGeometry geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), positions.size()));
    for (size_t i = 0; i < positions.size(); ++i) {
        for (int k = 0; k < 3; ++k) vertices[3 * i + k] = positions[i][k];
    }
    auto* indices = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(uint32_t), triangles.size()));
    for (size_t i = 0; i < triangles.size(); ++i) {
        for (int k = 0; k < 3; ++k) indices[3 * i + k] = triangles[i][k];
    }
    commit_alone(geometry, start, before, out);  // the buffers are Embree's
}

void build_point_in_polygon(const std::vector<std::vector<Vec3>>& gears, PolygonScene& out) {
    const long long before = embree_bytes_in_use();
    const auto start = std::chrono::steady_clock::now();
    for (const std::vector<Vec3>& outline : gears) {
        out.polygons.push_back(*PlanarPolygon::make(outline, FillRule::EvenOdd));
    }
    out.data = {out.polygons.data(), out.polygons.data()};
    RTCGeometry geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(out.polygons.size()));
    rtcSetGeometryUserData(geometry, &out.data);
    rtcSetGeometryBoundsFunction(geometry, user_bounds<PlanarPolygon>, nullptr);
    rtcSetGeometryIntersectFunction(geometry, user_intersect<PlanarPolygon>);
    rtcSetGeometryOccludedFunction(geometry, user_occluded<PlanarPolygon>);
    commit_alone(geometry, start, before, out);
    for (const PlanarPolygon& p : out.polygons) out.bytes += double(p.bytes());
}

template <void (*Build)(const std::vector<std::vector<Vec3>>&, PolygonScene&)>
void BM_Gears(benchmark::State& state) {
    const auto gears = gear_grid(static_cast<int>(state.range(0)));
    PolygonScene scene;
    Build(gears, scene);
    const float extent = kGearsPerSide * kSpacing;
    const Vec3 direction = glm::normalize(Vec3(0.2f, 0.1f, -1.0f));
    long long hits = 0;
    for (auto _ : state) {
        hits = 0;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (int y = 0; y < kRaysPerSide; ++y) {
            for (int x = 0; x < kRaysPerSide; ++x) {
                RTCRayHit rayhit{};
                rayhit.ray.org_x = -1.5f + extent * (x + 0.5f) / kRaysPerSide;
                rayhit.ray.org_y = -1.3f + extent * (y + 0.5f) / kRaysPerSide;
                rayhit.ray.org_z = 1.0f;
                rayhit.ray.dir_x = direction.x;
                rayhit.ray.dir_y = direction.y;
                rayhit.ray.dir_z = direction.z;
                rayhit.ray.tfar = 100.0f;
                rayhit.ray.mask = ~0u;
                rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(scene.scene, &context, &rayhit);
                hits += rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            }
        }
    }
    const double rays = double(kRaysPerSide) * kRaysPerSide;
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * rays));
    state.counters["vertices_per_polygon"] = double(gears[0].size());
    state.counters["build_ms"] = scene.build_seconds * 1e3;
    state.counters["MB"] = scene.bytes / 1e6;
    state.counters["hit_fraction"] = double(hits) / rays;
}

BENCHMARK_TEMPLATE(BM_Gears, build_triangles)->Arg(36)->Arg(360)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Gears, build_point_in_polygon)
    ->Arg(36)
    ->Arg(360)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rayo

RAYO_BENCHMARK_MAIN();
