// Blobs analytic against tessellated (issue 11 item 4; docs/csg-and-blobs.md): the blob of
// scenes/blobs.json's chain (five elements) traced by its own interval-bounded root search
// (core/shapes/blob.h) and as marching-tetrahedra meshes of growing resolution
// (core/shapes/blob_mesh.h), through the same accel, with the same rays: an R×R orthographic
// grid down −z over the blob's bounds, traced one by one on one thread.
//   build/blob_study [R]   (default 512)
// prints one CSV row per form: cells across the bounds (0: analytic), triangles, tessellation
// and BVH build seconds, Embree bytes, the mesh's own bytes (positions, normals, triangles),
// Mrays/s, and the error against the analytic hits in pixels of the grid (depth |Δt| mean, 99th
// percentile and max over rays both hit; rays hit by one form only).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/accel.h"
#include "core/float_mode.h"
#include "core/shapes/blob_mesh.h"

namespace rayo {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Blob chain() {
    Blob b;
    b.threshold = 0.35f;
    b.elements = {{Vec3(-3.6f, -0.3f, 0.6f), 1.1f, 1.0f},
                  {Vec3(-3.1f, 0.3f, 0.0f), 1.0f, 1.0f},
                  {Vec3(-2.5f, 0.7f, -0.5f), 0.9f, 1.0f},
                  {Vec3(-1.9f, 0.2f, 0.1f), 1.0f, 1.0f},
                  {Vec3(-1.6f, -0.4f, 0.8f), 0.8f, 1.0f}};
    return b;
}

struct Trace {
    std::vector<float> t;  // +inf: missed
    double seconds = 0.0;
};

Trace trace(const Accel& accel, const Bounds3& b, int r) {
    Trace out;
    out.t.resize(static_cast<size_t>(r) * r);
    const auto start = std::chrono::steady_clock::now();
    for (int j = 0; j < r; ++j) {
        for (int i = 0; i < r; ++i) {
            Ray ray;
            ray.origin =
                Vec3(b.lower.x + (b.upper.x - b.lower.x) * (i + 0.5f) / r,
                     b.lower.y + (b.upper.y - b.lower.y) * (j + 0.5f) / r, b.upper.z + 1.0f);
            ray.direction = Vec3(0, 0, -1);
            SurfaceHit hit;
            out.t[size_t(j) * r + i] =
                accel.intersect(ray, hit) ? hit.t : std::numeric_limits<float>::infinity();
        }
    }
    out.seconds = seconds_since(start);
    return out;
}

}  // namespace
}  // namespace rayo

int main(int argc, char** argv) {
    using namespace rayo;
    set_flush_denormals_to_zero();
    const int r = argc > 1 ? std::atoi(argv[1]) : 512;
    if (r < 8 || r > 8192) {
        std::fprintf(stderr, "usage: blob_study [R], 8 <= R <= 8192\n");
        return 2;
    }
    const Blob blob = chain();
    const Bounds3 b = blob.bounds();
    const double pixel = std::max(b.upper.x - b.lower.x, b.upper.y - b.lower.y) / r;
    const double extent =
        std::max({b.upper.x - b.lower.x, b.upper.y - b.lower.y, b.upper.z - b.lower.z});
    std::printf(
        "cells,triangles,tessellate_s,build_s,embree_bytes,mesh_bytes,mrays_s,err_mean_px,"
        "err_p99_px,err_max_px,hit_mismatches\n");
    Trace reference;
    for (const int cells : {0, 16, 32, 64, 128, 256, 512}) {
        Scene scene;
        double tessellate = 0.0;
        size_t triangles = 0, mesh_bytes = 0;
        if (cells == 0) {
            scene.shapes.of<Blob>().push_back(blob);
            mesh_bytes = blob.elements.size() * sizeof(BlobElement);
        } else {
            const auto start = std::chrono::steady_clock::now();
            TriangleMesh mesh = tessellate_blob(blob, extent / cells);
            tessellate = seconds_since(start);
            triangles = mesh.triangle_count();
            mesh_bytes = mesh.positions.size() * sizeof(Vec3) * 2 +
                         mesh.triangles.size() * (sizeof(mesh.triangles[0]) + sizeof(uint32_t));
            scene.meshes.push_back(std::move(mesh));
        }
        const auto start = std::chrono::steady_clock::now();
        const Accel accel(scene, AccelOptions{});
        const double build = seconds_since(start);
        const Trace run = trace(accel, b, r);
        if (cells == 0) reference = run;
        std::vector<double> errors;
        int mismatches = 0;
        for (size_t k = 0; k < run.t.size(); ++k) {
            const bool a = std::isfinite(reference.t[k]), m = std::isfinite(run.t[k]);
            if (a != m) ++mismatches;
            if (a && m) errors.push_back(std::abs(double(run.t[k]) - reference.t[k]) / pixel);
        }
        std::sort(errors.begin(), errors.end());
        double mean = 0.0;
        for (const double e : errors) mean += e;
        mean = errors.empty() ? 0.0 : mean / errors.size();
        const double p99 = errors.empty() ? 0.0 : errors[size_t(0.99 * (errors.size() - 1))];
        const double max = errors.empty() ? 0.0 : errors.back();
        std::printf("%d,%zu,%.4f,%.4f,%zu,%zu,%.3f,%.4f,%.4f,%.4f,%d\n", cells, triangles,
                    tessellate, build, accel.embree_bytes(), mesh_bytes,
                    double(run.t.size()) / run.seconds * 1e-6, mean, p99, max, mismatches);
    }
    return 0;
}
