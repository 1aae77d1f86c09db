// The height-field study (docs/heightfields.md): one synthetic DEM of N × N samples (fBm of
// sines, generated here: no data in the repository), one method (`dda`: the grid traversal as
// Embree user geometry; `mesh`: Embree triangles), and what it costs: build time, the bytes of
// the representation (rayo's own plus what Embree allocated), the process's peak RSS, and
// single-thread Mrays/s for 512 × 512 coherent camera rays over the field.
//   build/heightfield_study N dda|mesh    -> one CSV line on stdout
// bench/heightfield_study.sh runs it for N up to 8192 and draws the charts.
#include <sys/resource.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "core/accel.h"
#include "core/scene.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

long peak_rss_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss * 1024L;
}

// Terrain-like heights in [0, 1]: five octaves of products of sines, rotated per octave.
rayo::HeightField synthetic_dem(int n) {
    rayo::HeightField f;
    f.columns = f.rows = n;
    f.lower = rayo::Vec3(-50.0f, 0.0f, -50.0f);
    f.size = rayo::Vec3(100.0f, 12.0f, 100.0f);
    f.heights.resize(size_t(n) * size_t(n));
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const float x = float(i) / float(n - 1) * 6.0f, z = float(j) / float(n - 1) * 6.0f;
            float h = 0.0f, amplitude = 0.5f, frequency = 1.0f;
            for (int octave = 0; octave < 5; ++octave) {
                const float a = 0.7f * float(octave);
                const float u = std::cos(a) * x - std::sin(a) * z,
                            v = std::sin(a) * x + std::cos(a) * z;
                h += amplitude * std::sin(frequency * u + 1.3f * float(octave)) *
                     std::sin(frequency * v * 1.1f);
                amplitude *= 0.5f;
                frequency *= 2.1f;
            }
            f.heights[size_t(j) * size_t(n) + size_t(i)] = f.size.y * (0.5f + 0.5f * h);
        }
    }
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3 || (std::string(argv[2]) != "dda" && std::string(argv[2]) != "mesh")) {
        std::cerr << "usage: heightfield_study N dda|mesh\n";
        return 2;
    }
    const int n = std::stoi(argv[1]);
    const bool mesh = std::string(argv[2]) == "mesh";
    // One thread for the build and the rays: the machine is shared; the figures compare forms.
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);

    rayo::Scene scene;
    rayo::HeightField field = synthetic_dem(n);
    const long rss_before = peak_rss_bytes();
    const auto build_start = Clock::now();
    size_t own_bytes = 0;
    if (mesh) {
        scene.meshes.push_back(field.tessellate());
        const rayo::TriangleMesh& m = scene.meshes.back();
        own_bytes = m.positions.size() * sizeof(rayo::Vec3) +
                    m.triangles.size() * sizeof(m.triangles[0]) +
                    m.materials.size() * sizeof(uint32_t);
        field = rayo::HeightField{};  // the samples are no longer needed
    } else {
        field.finish();
        own_bytes = field.traversal_bytes();
        scene.heightfields.push_back(std::move(field));
    }
    const auto accel = std::make_unique<rayo::Accel>(scene);
    const double build_s = seconds_since(build_start);

    // 512 × 512 pinhole rays from above one corner toward the middle (60° field of view).
    const int side = 512;
    const rayo::Vec3 eye(-70.0f, 45.0f, -70.0f), target(0.0f, 0.0f, 0.0f);
    const rayo::Vec3 w = glm::normalize(target - eye);
    const rayo::Vec3 u = glm::normalize(glm::cross(w, rayo::Vec3(0, 1, 0)));
    const rayo::Vec3 v = glm::cross(u, w);
    std::vector<rayo::Ray> rays(size_t(side) * side);
    for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
            const float px = (float(x) + 0.5f) / side * 2.0f - 1.0f;
            const float py = (float(y) + 0.5f) / side * 2.0f - 1.0f;
            rays[size_t(y) * side + x].origin = eye;
            rays[size_t(y) * side + x].direction = glm::normalize(w + 0.577f * (px * u - py * v));
        }
    }
    std::vector<rayo::SurfaceHit> hits(rays.size());
    std::unique_ptr<bool[]> found(new bool[rays.size()]);
    const auto trace_start = Clock::now();
    accel->intersect_coherent(rays.data(), int(rays.size()), hits.data(), found.get());
    const double trace_s = seconds_since(trace_start);
    size_t hit_count = 0;
    double t_sum = 0.0;
    for (size_t i = 0; i < rays.size(); ++i) {
        if (found[i]) {
            ++hit_count;
            t_sum += hits[i].t;
        }
    }
    // samples,method,build_s,own_bytes,embree_bytes,peak_rss_bytes,rss_before_build,mrays_s,
    // hits,mean_t
    std::cout << n << "," << argv[2] << "," << build_s << "," << own_bytes << ","
              << accel->embree_bytes() << "," << peak_rss_bytes() << "," << rss_before << ","
              << double(rays.size()) / trace_s * 1e-6 << "," << hit_count << ","
              << (hit_count ? t_sum / double(hit_count) : 0.0) << "\n";
    return 0;
}
