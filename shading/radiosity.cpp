#include "shading/radiosity.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <utility>

#include "core/sampling.h"

namespace rayo {

namespace {

constexpr double kPiD = 3.14159265358979323846;

double channel_sum(const DVec3& v) {
    return v.x + v.y + v.z;
}

// Sutherland–Hodgman: the part of the polygon on the side `normal` points to from `point`.
int clip_to_half_space(const DVec3& point, const DVec3& normal, const DVec3* in, int n,
                       DVec3* out) {
    int m = 0;
    for (int k = 0; k < n; ++k) {
        const DVec3& a = in[k];
        const DVec3& b = in[(k + 1) % n];
        const double da = glm::dot(normal, a - point);
        const double db = glm::dot(normal, b - point);
        if (da >= 0.0) out[m++] = a;
        if ((da >= 0.0) != (db >= 0.0)) out[m++] = a + (b - a) * (da / (da - db));
    }
    return m;
}

// A point of the triangle from u in [0,1)²: area-uniform (s = √u1).
Vec3 triangle_point(const RadiosityPatch& p, float u1, float u2) {
    const float s = std::sqrt(u1);
    return p.vertices[0] * (1.0f - s) + p.vertices[1] * (s * (1.0f - u2)) +
           p.vertices[2] * (s * u2);
}

// Stratum k of a g-column grid over [0,1)², jittered by (j1, j2).
glm::vec2 stratum(int k, int g, int rows, float j1, float j2) {
    return glm::vec2((static_cast<float>(k % g) + j1) / static_cast<float>(g),
                     (static_cast<float>(k / g) + j2) / static_cast<float>(rows));
}

}  // namespace

RadiosityPatch make_patch(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& emission,
                          const Vec3& reflectance) {
    RadiosityPatch p;
    p.vertices = {a, b, c};
    const Vec3 cross = glm::cross(b - a, c - a);
    const float length = glm::length(cross);
    p.area = 0.5f * length;
    p.normal = length > 0.0f ? cross / length : Vec3(0.0f);
    p.emission = emission;
    p.reflectance = reflectance;
    return p;
}

double point_polygon_form_factor(const DVec3& point, const DVec3& normal, const DVec3* polygon,
                                 int n) {
    // A triangle clipped by a plane keeps at most 4 vertices; a quad 5: 16 is ample.
    DVec3 clipped[16];
    const int m = clip_to_half_space(point, normal, polygon, std::min(n, 8), clipped);
    if (m < 3) return 0.0;
    double sum = 0.0;
    for (int k = 0; k < m; ++k) {
        const DVec3 a = clipped[k] - point;
        const DVec3 b = clipped[(k + 1) % m] - point;
        const DVec3 c = glm::cross(a, b);
        const double c_length = glm::length(c);
        if (c_length <= 0.0) continue;  // an edge through the point, or a degenerate edge
        const double gamma = std::atan2(c_length, glm::dot(a, b));  // angle between Rk, Rk+1
        sum += gamma * glm::dot(normal, c) / c_length;
    }
    return std::abs(sum) / (2.0 * kPiD);
}

double analytic_form_factor(const RadiosityPatch& receiver, const RadiosityPatch& source,
                            int grid) {
    const DVec3 polygon[3] = {DVec3(source.vertices[0]), DVec3(source.vertices[1]),
                              DVec3(source.vertices[2])};
    const DVec3 a(receiver.vertices[0]), b(receiver.vertices[1]), c(receiver.vertices[2]);
    const DVec3 normal(receiver.normal);
    const double g = grid;
    double sum = 0.0;
    int count = 0;
    // The centroids of the grid² congruent triangles of the regular subdivision (equal areas).
    auto add = [&](double s, double t) {
        sum += point_polygon_form_factor(a + (b - a) * s + (c - a) * t, normal, polygon, 3);
        ++count;
    };
    for (int i = 0; i < grid; ++i) {
        for (int j = 0; i + j < grid; ++j) {
            add((i + 1.0 / 3.0) / g, (j + 1.0 / 3.0) / g);
            if (i + j < grid - 1) add((i + 2.0 / 3.0) / g, (j + 2.0 / 3.0) / g);
        }
    }
    return sum / count;
}

bool patches_face_away(const RadiosityPatch& a, const RadiosityPatch& b) {
    auto behind = [](const RadiosityPatch& plane, const RadiosityPatch& other) {
        const float scale = glm::length(plane.vertices[1] - plane.vertices[0]) +
                            glm::length(plane.vertices[2] - plane.vertices[0]);
        for (const Vec3& v : other.vertices) {
            if (glm::dot(plane.normal, v - plane.vertices[0]) > 1e-6f * scale) return false;
        }
        return true;
    };
    return behind(a, b) || behind(b, a);
}

double ray_form_factor(const Accel& accel, const RadiosityPatch& receiver,
                       const RadiosityPatch& source, int rays, uint32_t seed, uint64_t& traced) {
    // √rays stratified points y on the receiver, each with rays/√rays shadow rays to stratified
    // points x on the source.
    const int points = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(rays))));
    const int per_point = std::max(1, rays / points);
    const int gy = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(points))));
    const int gx = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(per_point))));
    const DVec3 polygon[3] = {DVec3(source.vertices[0]), DVec3(source.vertices[1]),
                              DVec3(source.vertices[2])};
    const float offset = 1e-4f * (max_abs_component(receiver.vertices[0]) +
                                  glm::length(receiver.vertices[1] - receiver.vertices[0]));
    constexpr int kBatch = Accel::kCoherentBatch;
    Ray batch[kBatch];
    float weights[kBatch];
    bool occluded[kBatch];
    double sum = 0.0;
    for (int a = 0; a < points; ++a) {
        const glm::vec2 uy = stratum(a, gy, (points + gy - 1) / gy, sample_uniform(seed, a, 0, 0),
                                     sample_uniform(seed, a, 0, 1));
        const Vec3 y = triangle_point(receiver, std::min(uy.x, 1.0f), std::min(uy.y, 1.0f));
        const double f_point =
            point_polygon_form_factor(DVec3(y), DVec3(receiver.normal), polygon, 3);
        if (f_point <= 0.0) continue;
        const Vec3 origin = y + receiver.normal * (offset + receiver.lift);
        double seen = 0.0, total = 0.0;
        for (int first = 0; first < per_point; first += kBatch) {
            int pending = 0;
            for (int b = first; b < std::min(per_point, first + kBatch); ++b) {
                const glm::vec2 ux =
                    stratum(b, gx, (per_point + gx - 1) / gx, sample_uniform(seed, a, b + 1, 0),
                            sample_uniform(seed, a, b + 1, 1));
                Vec3 x = triangle_point(source, std::min(ux.x, 1.0f), std::min(ux.y, 1.0f));
                if (source.lift > 0.0f) x += source.normal * source.lift;
                const Vec3 to_x = x - origin;
                const float r2 = glm::dot(to_x, to_x);
                if (r2 <= 0.0f) continue;
                const float r = std::sqrt(r2);
                const Vec3 d = to_x / r;
                const float cos_y = glm::dot(receiver.normal, d);
                const float cos_x = -glm::dot(source.normal, d);
                if (cos_y <= 0.0f || cos_x <= 0.0f) continue;
                Ray& ray = batch[pending];
                ray.origin = origin;
                ray.direction = d;
                ray.tnear = 0.0f;
                ray.tfar = r * (1.0f - 1e-4f);
                weights[pending] = cos_y * cos_x / r2;
                ++pending;
            }
            if (pending == 0) continue;
            accel.occluded_coherent(batch, pending, occluded);
            traced += static_cast<uint64_t>(pending);
            for (int k = 0; k < pending; ++k) {
                total += weights[k];
                if (!occluded[k]) seen += weights[k];
            }
        }
        if (total > 0.0) sum += f_point * (seen / total);
    }
    return sum / points;
}

std::vector<DVec3> solve_radiosity_gauss_seidel(const std::vector<double>& form_factors,
                                                const std::vector<DVec3>& emission,
                                                const std::vector<DVec3>& reflectance,
                                                double tolerance, int max_iterations,
                                                int* iterations) {
    const size_t n = emission.size();
    std::vector<DVec3> b = emission;
    int sweep = 0;
    while (sweep < max_iterations) {
        ++sweep;
        double change = 0.0;
        for (size_t i = 0; i < n; ++i) {
            // Bi·(1 − ρi·Fii) = Ei + ρi·Σj≠i Fij·Bj
            DVec3 gathered(0.0);
            for (size_t j = 0; j < n; ++j) {
                if (j != i) gathered += form_factors[i * n + j] * b[j];
            }
            const DVec3 next = (emission[i] + reflectance[i] * gathered) /
                               (DVec3(1.0) - reflectance[i] * form_factors[i * n + i]);
            const DVec3 delta = glm::abs(next - b[i]);
            change = std::max(change, std::max(delta.x, std::max(delta.y, delta.z)));
            b[i] = next;
        }
        if (change <= tolerance) break;
    }
    if (iterations) *iterations = sweep;
    return b;
}

ProgressiveRadiosity::ProgressiveRadiosity(std::vector<double> areas, std::vector<DVec3> emission,
                                           std::vector<DVec3> reflectance, FormFactorColumn column)
    : m_areas(std::move(areas)),
      m_reflectance(std::move(reflectance)),
      m_column(std::move(column)),
      m_radiosity(emission),
      m_unshot(std::move(emission)),
      m_f(m_areas.size(), 0.0) {
    m_emitted = unshot_energy();
}

double ProgressiveRadiosity::unshot_energy() const {
    double total = 0.0;
    for (size_t i = 0; i < m_unshot.size(); ++i) total += channel_sum(m_unshot[i]) * m_areas[i];
    return total;
}

int ProgressiveRadiosity::shoot() {
    int shooter = -1;
    double most = 0.0;
    for (size_t i = 0; i < m_unshot.size(); ++i) {
        const double energy = channel_sum(m_unshot[i]) * m_areas[i];
        if (energy > most) {
            most = energy;
            shooter = static_cast<int>(i);
        }
    }
    if (shooter < 0) return -1;
    const size_t i = static_cast<size_t>(shooter);
    std::fill(m_f.begin(), m_f.end(), 0.0);
    m_column(i, m_f);
    const DVec3 shot = m_unshot[i];
    m_unshot[i] = DVec3(0.0);
    for (size_t j = 0; j < m_f.size(); ++j) {
        if (j == i || m_f[j] == 0.0) continue;
        const DVec3 delta = m_reflectance[j] * m_f[j] * shot;  // ΔBj = ρj·Fji·ΔBi
        m_radiosity[j] += delta;
        m_unshot[j] += delta;
    }
    ++m_shots;
    return shooter;
}

std::vector<DVec3> solve_radiosity(const std::vector<RadiosityPatch>& patches, const Accel* accel,
                                   const RadiositySettings& settings, RadiosityStats& stats,
                                   const std::function<void(double)>& on_shot) {
    const auto start = std::chrono::steady_clock::now();
    const size_t n = patches.size();
    std::vector<double> areas(n);
    std::vector<DVec3> emission(n), reflectance(n);
    for (size_t i = 0; i < n; ++i) {
        areas[i] = patches[i].area;
        emission[i] = DVec3(patches[i].emission);
        reflectance[i] = DVec3(patches[i].reflectance);
    }
    const int rays = std::max(1, settings.rays);
    const int grid = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(rays))));
    std::atomic<uint64_t> traced{0};
    auto column = [&](size_t shooter, std::vector<double>& f) {
        const RadiosityPatch& source = patches[shooter];
        // Each receiver's value depends only on (receiver, shooter): the same for any thread
        // count and partition.
        tbb::parallel_for(
            tbb::blocked_range<size_t>(0, n), [&](const tbb::blocked_range<size_t>& r) {
                uint64_t local = 0;
                for (size_t j = r.begin(); j != r.end(); ++j) {
                    const RadiosityPatch& receiver = patches[j];
                    if (j == shooter || receiver.area <= 0.0f ||
                        receiver.reflectance == Vec3(0.0f) || patches_face_away(receiver, source)) {
                        f[j] = 0.0;
                        continue;
                    }
                    if (settings.form_factors == FormFactorMethod::Analytic || accel == nullptr) {
                        f[j] = analytic_form_factor(receiver, source, grid);
                    } else {
                        const uint32_t seed = hash_combine(hash_u32(static_cast<uint32_t>(j)),
                                                           static_cast<uint32_t>(shooter));
                        f[j] = ray_form_factor(*accel, receiver, source, rays, seed, local);
                    }
                }
                traced.fetch_add(local, std::memory_order_relaxed);
            });
    };
    ProgressiveRadiosity solver(std::move(areas), std::move(emission), std::move(reflectance),
                                column);
    const double emitted = solver.emitted_energy();
    stats = RadiosityStats{};
    double fraction = emitted > 0.0 ? 1.0 : 0.0;
    while (fraction > settings.threshold && solver.shots() < settings.max_shots) {
        if (solver.shoot() < 0) break;
        fraction = solver.unshot_energy() / emitted;
        stats.history.push_back(fraction);
        if (on_shot) on_shot(fraction);
    }
    stats.shots = solver.shots();
    stats.unshot_fraction = emitted > 0.0 ? solver.unshot_energy() / emitted : 0.0;
    stats.form_factor_rays = traced.load();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return solver.radiosity();
}

}  // namespace rayo
