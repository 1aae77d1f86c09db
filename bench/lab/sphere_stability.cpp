#include "bench/lab/sphere_stability.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>

#include "bench/lab/study_stop.h"
#include "core/shapes/quadric.h"
#include "core/shapes/quadric_forms.h"

namespace rayo {
namespace {

using LD = long double;

struct LVec {
    LD x = 0, y = 0, z = 0;
};

LVec operator+(const LVec& a, const LVec& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
LVec operator-(const LVec& a, const LVec& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
LVec operator*(LD s, const LVec& a) {
    return {s * a.x, s * a.y, s * a.z};
}
LD dot(const LVec& a, const LVec& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
LVec cross(const LVec& a, const LVec& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
LVec normalized(const LVec& a) {
    return (1.0L / std::sqrt(dot(a, a))) * a;
}
LVec widen(const Vec3& v) {
    return {LD(v.x), LD(v.y), LD(v.z)};
}
// Rounds each component to the nearest float (what a float scene stores).
Vec3 narrow(const LVec& v) {
    return Vec3(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}

float float_ulp(double magnitude) {
    const auto f = static_cast<float>(magnitude);
    return std::nextafter(f, std::numeric_limits<float>::infinity()) - f;
}

// The centre of every configuration: along (1, 0.5, −0.75)·magnitude plus a fraction of a float
// ulp of the magnitude, so that rounding it to float moves it (Intended reference).
LVec study_center(double magnitude) {
    if (magnitude == 0.0) return {};
    const LD m = magnitude, ulp = float_ulp(magnitude);
    return {m + 0.31L * ulp, 0.5L * m - 0.23L * ulp, -0.75L * m + 0.43L * ulp};
}

struct Rng {
    explicit Rng(uint32_t seed) : engine(seed) {}
    double uniform() { return std::uniform_real_distribution<double>(0.0, 1.0)(engine); }
    // Uniform on the unit sphere.
    LVec unit() {
        const LD z = 2.0L * uniform() - 1.0L, phi = 2.0L * 3.14159265358979323846L * uniform();
        const LD s = std::sqrt(std::max(LD(0), 1.0L - z * z));
        return {s * std::cos(phi), s * std::sin(phi), z};
    }
    // A uniformly random unit vector perpendicular to unit `u`.
    LVec perpendicular(const LVec& u) {
        const LVec helper = std::fabs(u.x) < 0.6L ? LVec{1, 0, 0} : LVec{0, 1, 0};
        const LVec e1 = normalized(cross(u, helper)), e2 = cross(u, e1);
        const LD phi = 2.0L * 3.14159265358979323846L * uniform();
        return std::cos(phi) * e1 + std::sin(phi) * e2;
    }
    std::mt19937 engine;
};

// The line origin + t·direction (direction of any length) against the sphere, in long double
// with the stable form (docs/architecture.md "Numerics", generalised to |d| ≠ 1): a·t² + 2b·t + c =
// 0 with a = d·d, b = f·d, c = (|f|−r)(|f|+r); Δ/4 = a·r² − |f×d|² (Lagrange's identity: the
// perpendicular distance, no cancellation of b² against a·c); roots q/a and c/q.
struct Reference {
    bool hit = false;  // a root in (0, ∞)
    LD t = 0;          // the nearest such root
    LD far_root = 0;   // the larger root (valid when both roots exist)
    bool has_roots = false;
    bool tangent_band = false;  // |p − r| ≤ kTangentBand·r
    LD rim_distance = 0;        // |p − r| / r
};

Reference solve_reference(const LVec& origin, const LVec& direction, const LVec& center,
                          LD radius) {
    Reference ref;
    const LVec f = origin - center;
    const LD a = dot(direction, direction), b = dot(f, direction);
    const LVec fxd = cross(f, direction);
    const LD perpendicular = std::sqrt(dot(fxd, fxd) / a);
    ref.rim_distance = std::fabs(perpendicular - radius) / radius;
    ref.tangent_band = ref.rim_distance <= LD(kTangentBand);
    const LD discriminant = a * radius * radius - dot(fxd, fxd);
    if (!(discriminant > 0)) return ref;
    const LD length_f = std::sqrt(dot(f, f));
    const LD c = (length_f - radius) * (length_f + radius);
    const LD q = -(b + std::copysign(std::sqrt(discriminant), b));
    LD t0 = q / a, t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    ref.has_roots = true;
    ref.far_root = t1;
    if (t0 > 0) {
        ref.hit = true;
        ref.t = t0;
    } else if (t1 > 0) {
        ref.hit = true;
        ref.t = t1;
    }
    return ref;
}

struct StudyRay {
    Vec3 origin, direction;        // what the methods get
    LVec origin_ld, direction_ld;  // the intended ray
};

// The ray set of one configuration (see RayPattern); deterministic for a seed.
std::vector<StudyRay> make_rays(const StabilityCase& c, const LVec& center) {
    Rng rng(c.seed);
    std::vector<StudyRay> rays;
    rays.reserve(static_cast<size_t>(std::max(c.rays, 0)));
    const LD r = c.radius;
    for (int i = 0; i < c.rays; ++i) {
        const LVec u = rng.unit();
        const LVec e = rng.perpendicular(u);
        StudyRay ray;
        if (c.pattern == RayPattern::Disk || c.pattern == RayPattern::Grazing) {
            // From D radii along u, passing the centre at perpendicular distance p: the angle α
            // off the direction to the centre has sin α = p / (D·r).
            const LD distance = LD(c.distance_ratio) * r;
            LD p;
            if (c.pattern == RayPattern::Disk) {
                const LD reach = std::min(LD(1 + c.aim), LD(c.distance_ratio)) * r;
                p = reach * std::sqrt(LD(rng.uniform()));  // uniform over the disk's area
            } else {
                p = std::min(LD(1 + c.aim) * r, distance);
            }
            const LD sin_a = p / distance, cos_a = std::sqrt(std::max(LD(0), 1 - sin_a * sin_a));
            ray.origin_ld = center + distance * u;
            ray.direction_ld = (-cos_a) * u + sin_a * e;
        } else {
            // On the surface (moved `aim` radii along the normal), cos θ from the normal uniform
            // in [0.05, 1]: away from the tangent plane, which the Disk/Grazing rows cover.
            const LD cos_t = 0.05L + 0.95L * LD(rng.uniform());
            const LD sin_t = std::sqrt(1 - cos_t * cos_t);
            const LD side = c.pattern == RayPattern::SurfaceOutward ? 1.0L : -1.0L;
            ray.origin_ld = center + (r * LD(1 + c.aim)) * u;
            ray.direction_ld = (side * cos_t) * u + sin_t * e;
        }
        ray.origin = narrow(ray.origin_ld);
        ray.direction = narrow(ray.direction_ld);
        rays.push_back(ray);
    }
    return rays;
}

bool intersect_direct(SphereMath math, const StudyRay& ray, const Vec3& center, float radius,
                      float& t) {
    bool far_root;
    return intersect_sphere(math, ray.origin, ray.direction, center, radius, 0.0f,
                            std::numeric_limits<float>::infinity(), t, far_root);
}

// The sphere as a quadric shape (StudyShape): its intersector, built once per case.
ClippedQuadric sphere_as_quadric(StudyShape shape, const Vec3& center, float radius) {
    if (shape == StudyShape::Ellipsoid) {
        Ellipsoid e;
        e.center = center;
        e.radii = Vec3(radius);
        return e.intersector();
    }
    // |x − c|² − r² expanded: the world-space coefficients a scene file would hold (double, as
    // the shape keeps them), from the float centre and radius.
    const DVec3 c(center);
    const double r = radius;
    Quadric q;
    q.coefficients = {1, 1, 1, 0, 0, 0, -2.0 * c.x, -2.0 * c.y, -2.0 * c.z, glm::dot(c, c) - r * r};
    q.clip = {center - Vec3(2.0f * radius), center + Vec3(2.0f * radius)};
    return q.intersector();
}

bool intersect_quadric(const ClippedQuadric& quadric, const StudyRay& ray, float& t) {
    ShapeHit hit;
    if (!quadric.nearest(ray.origin, ray.direction, 0.0f, std::numeric_limits<float>::infinity(),
                         hit)) {
        return false;
    }
    t = hit.t;
    return true;
}

bool intersect_accel(const Accel& accel, const StudyRay& ray, float& t) {
    Ray r;
    r.origin = ray.origin;
    r.direction = ray.direction;
    SurfaceHit hit;
    if (!accel.intersect(r, hit)) return false;
    t = hit.t;
    return true;
}

AccelOptions accel_options(const StudyMethod& m) {
    AccelOptions o;
    o.spheres.method = m.method;
    o.spheres.mesh_level = m.mesh_level;
    o.sphere_math = m.math;
    return o;
}

bool all_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

double median_of(std::vector<double>& v) {
    if (v.empty()) return 0.0;
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
    double m = v[mid];
    if (v.size() % 2 == 0) {
        m = 0.5 * (m + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid)));
    }
    return m;
}

}  // namespace

std::string study_method_name(const StudyMethod& m) {
    if (m.shape == StudyShape::General) return "quadric";
    if (m.shape == StudyShape::Ellipsoid) return "ellipsoid";
    if (m.method == SphereMethod::BruteForce) return "analytic";
    SphereRepresentation r;
    r.method = m.method;
    r.mesh_level = m.mesh_level;
    return sphere_method_name(r);
}

std::string study_math_name(const StudyMethod& m) {
    if (m.method == SphereMethod::BruteForce || m.method == SphereMethod::User) {
        return sphere_math_name(m.math);
    }
    return "embree";
}

std::vector<StudyMethod> default_study_methods() {
    std::vector<StudyMethod> methods;
    for (SphereMethod method : {SphereMethod::BruteForce, SphereMethod::User}) {
        for (SphereMath math : {SphereMath::Seed, SphereMath::Stable, SphereMath::Double}) {
            methods.push_back({method, math, 0});
        }
    }
    methods.push_back({SphereMethod::EmbreePoint, SphereMath::Stable, 0});
    methods.push_back({SphereMethod::Mesh, SphereMath::Stable, 2});
    methods.push_back({SphereMethod::Mesh, SphereMath::Stable, 5});
    return methods;
}

std::vector<StudyMethod> quadric_study_methods() {
    std::vector<StudyMethod> methods;
    methods.push_back({SphereMethod::BruteForce, SphereMath::Stable, 0});
    methods.push_back({SphereMethod::BruteForce, SphereMath::Double, 0});
    methods.push_back({SphereMethod::BruteForce, SphereMath::Double, 0, StudyShape::General});
    methods.push_back({SphereMethod::BruteForce, SphereMath::Double, 0, StudyShape::Ellipsoid});
    return methods;
}

const char* ray_pattern_name(RayPattern p) {
    switch (p) {
        case RayPattern::Disk:
            return "disk";
        case RayPattern::Grazing:
            return "grazing";
        case RayPattern::SurfaceInward:
            return "surface-in";
        case RayPattern::SurfaceOutward:
            return "surface-out";
    }
    return "?";
}

const char* reference_problem_name(ReferenceProblem r) {
    return r == ReferenceProblem::Rounded ? "rounded" : "intended";
}

std::vector<StabilityRow> run_stability_case(const StabilityCase& c,
                                             const std::vector<StudyMethod>& methods) {
    if (!(c.radius > 0.0) || !std::isfinite(c.radius) || !std::isfinite(c.center_magnitude) ||
        !(c.distance_ratio >= 1.0) || !std::isfinite(c.distance_ratio) || !std::isfinite(c.aim) ||
        c.rays < 0) {
        throw std::invalid_argument(
            "stability case: expected a finite radius > 0, distance ratio >= 1, finite aim and "
            "centre magnitude, rays >= 0");
    }
    const LVec center_ld = study_center(c.center_magnitude);
    const std::vector<StudyRay> rays = make_rays(c, center_ld);
    const Vec3 center = narrow(center_ld);
    const auto radius = static_cast<float>(c.radius);

    // The reference of every ray, once.
    std::vector<Reference> refs;
    refs.reserve(rays.size());
    for (const StudyRay& ray : rays) {
        if (c.reference == ReferenceProblem::Rounded) {
            refs.push_back(solve_reference(widen(ray.origin), widen(ray.direction), widen(center),
                                           LD(radius)));
        } else {
            refs.push_back(
                solve_reference(ray.origin_ld, ray.direction_ld, center_ld, LD(c.radius)));
        }
    }

    Scene scene;
    scene.shapes.of<Sphere>().push_back(Sphere{center, radius, 0});
    std::vector<StabilityRow> rows;
    for (const StudyMethod& m : methods) {
        std::unique_ptr<Accel> accel;
        if (m.method != SphereMethod::BruteForce) {
            accel = std::make_unique<Accel>(scene, accel_options(m));
        }
        const ClippedQuadric quadric = sphere_as_quadric(m.shape, center, radius);
        StabilityRow row;
        row.config = c;
        row.method = study_method_name(m);
        row.math = study_math_name(m);
        row.precision = m.math == SphereMath::Double && (m.method == SphereMethod::BruteForce ||
                                                         m.method == SphereMethod::User)
                            ? "double"
                            : "float";
        row.rays = static_cast<int>(rays.size());
        if (m.method == SphereMethod::User) row.direct_mismatches = 0;
        std::vector<double> errors;
        for (size_t i = 0; i < rays.size(); ++i) {
            float t = 0.0f;
            const bool hit = accel ? intersect_accel(*accel, rays[i], t)
                             : m.shape != StudyShape::Sphere
                                 ? intersect_quadric(quadric, rays[i], t)
                                 : intersect_direct(m.math, rays[i], center, radius, t);
            if (m.method == SphereMethod::User) {
                float direct_t = 0.0f;
                const bool direct_hit = intersect_direct(m.math, rays[i], center, radius, direct_t);
                if (hit != direct_hit || (hit && t != direct_t)) ++row.direct_mismatches;
            }
            const Reference& ref = refs[i];
            if (hit && ref.hit) {
                errors.push_back(static_cast<double>(std::fabs(LD(t) - ref.t) / ref.t));
            }
            if (ref.tangent_band) {
                ++row.excluded;
                continue;
            }
            if (ref.hit) ++row.reference_hits;
            if (hit != ref.hit) {
                ++(hit ? row.wrong_hits : row.wrong_misses);
                row.wrong_rim_max = std::max(row.wrong_rim_max, double(ref.rim_distance));
            }
        }
        const int counted = row.rays - row.excluded;
        row.wrong_rate =
            counted > 0 ? double(row.wrong_hits + row.wrong_misses) / double(counted) : 0.0;
        row.both_hit = static_cast<int>(errors.size());
        row.t_rel_max = errors.empty() ? 0.0 : *std::max_element(errors.begin(), errors.end());
        row.t_rel_median = median_of(errors);
        rows.push_back(std::move(row));
    }
    return rows;
}

namespace {

void append(std::vector<StabilityRow>& to, std::vector<StabilityRow> rows) {
    to.insert(to.end(), std::make_move_iterator(rows.begin()), std::make_move_iterator(rows.end()));
}

StabilityCase base_case(const StabilityConfig& c, uint32_t index) {
    StabilityCase s;
    s.rays = c.rays;
    s.seed = c.seed + 7919u * index;  // a distinct, deterministic ray set per configuration
    return s;
}

}  // namespace

std::vector<StabilityRow> run_distance_sweep(const StabilityConfig& c) {
    std::vector<StabilityRow> rows;
    uint32_t index = 0;
    for (double d : c.distance_ratios) {
        stop_study_if_requested("stability sweep");
        StabilityCase s = base_case(c, index++);
        s.pattern = RayPattern::Disk;
        s.distance_ratio = d;
        s.aim = 0.25;
        append(rows, run_stability_case(s, c.methods));
    }
    return rows;
}

std::vector<StabilityRow> run_grazing_sweep(const StabilityConfig& c) {
    std::vector<StabilityRow> rows;
    uint32_t index = 100;
    for (double d : c.grazing_distances) {
        for (double offset : c.grazing_offsets) {
            for (double sign : {+1.0, -1.0}) {
                StabilityCase s = base_case(c, index++);
                s.pattern = RayPattern::Grazing;
                s.distance_ratio = d;
                s.aim = sign * offset;
                append(rows, run_stability_case(s, c.methods));
            }
        }
    }
    return rows;
}

std::vector<StabilityRow> run_surface_sweep(const StabilityConfig& c) {
    std::vector<StabilityRow> rows;
    uint32_t index = 200;
    for (double magnitude : c.surface_magnitudes) {
        for (double offset : c.surface_offsets) {
            for (RayPattern p : {RayPattern::SurfaceInward, RayPattern::SurfaceOutward}) {
                StabilityCase s = base_case(c, index++);
                s.pattern = p;
                s.center_magnitude = magnitude;
                s.aim = offset;
                append(rows, run_stability_case(s, c.methods));
            }
        }
    }
    return rows;
}

std::vector<StabilityRow> run_scale_sweep(const StabilityConfig& c) {
    std::vector<StabilityRow> rows;
    uint32_t index = 300;
    for (ReferenceProblem reference : {ReferenceProblem::Rounded, ReferenceProblem::Intended}) {
        for (double radius : c.scale_radii) {
            for (double magnitude : c.scale_magnitudes) {
                StabilityCase s = base_case(c, index++);
                s.radius = radius;
                s.center_magnitude = magnitude;
                s.reference = reference;
                append(rows, run_stability_case(s, c.methods));
            }
        }
    }
    return rows;
}

std::vector<StabilityRow> run_breaking_point_sweep(const StabilityConfig& c) {
    std::vector<StabilityRow> rows;
    uint32_t index = 400;
    const double ulp = float_ulp(c.breaking_magnitude);
    for (double ulps : c.breaking_ulps) {
        StabilityCase s = base_case(c, index++);
        s.radius = ulps * ulp;
        s.center_magnitude = c.breaking_magnitude;
        s.reference = ReferenceProblem::Intended;
        append(rows, run_stability_case(s, c.methods));
    }
    return rows;
}

std::vector<StabilityRow> run_stability_study(const StabilityConfig& c) {
    std::vector<StabilityRow> rows = run_distance_sweep(c);
    append(rows, run_grazing_sweep(c));
    append(rows, run_surface_sweep(c));
    append(rows, run_scale_sweep(c));
    append(rows, run_breaking_point_sweep(c));
    return rows;
}

std::vector<StabilityRow> run_quadric_study(StabilityConfig c) {
    c.methods = quadric_study_methods();
    std::vector<StabilityRow> rows = run_distance_sweep(c);
    append(rows, run_grazing_sweep(c));
    append(rows, run_scale_sweep(c));
    return rows;
}

// --- spawned-ray self-intersection ---

const char* offset_method_name(OffsetMethod m) {
    switch (m) {
        case OffsetMethod::None:
            return "none";
        case OffsetMethod::FixedEpsilon:
            return "fixed-1e-4";
        case OffsetMethod::PositionScaled:
            return "position-scaled";
    }
    return "?";
}

const char* spawn_kind_name(SpawnKind k) {
    return k == SpawnKind::Reflection ? "reflection" : "refraction";
}

namespace {

void check_offset_case(const OffsetCase& c, const OffsetFunction& scaled) {
    if (!(c.radius > 0.0) || !std::isfinite(c.radius) || !std::isfinite(c.center_magnitude) ||
        !(c.distance_ratio > 1.0) || !std::isfinite(c.distance_ratio) || c.rays < 0) {
        throw std::invalid_argument(
            "offset case: expected a finite radius > 0, distance ratio > 1, finite centre "
            "magnitude, rays >= 0");
    }
    if (c.offset == OffsetMethod::PositionScaled && !scaled) {
        throw std::invalid_argument(
            "offset case: the position-scaled method needs the offset function "
            "(rayo::offset_ray_origin)");
    }
}

OffsetRow run_offset_case_with(const OffsetCase& c, const Accel& accel, const Vec3& center,
                               float radius, const OffsetFunction& scaled) {
    check_offset_case(c, scaled);
    OffsetRow row;
    row.config = c;
    row.rays = c.rays;
    Rng rng(c.seed);
    const LD distance = LD(c.distance_ratio) * LD(radius);
    for (int i = 0; i < c.rays; ++i) {
        // A camera-like primary ray aimed within 0.9 radii of the centre (no grazing hits).
        const LVec u = rng.unit(), e = rng.perpendicular(u);
        const LD sin_a = 0.9L * LD(radius) * std::sqrt(LD(rng.uniform())) / distance;
        Ray primary;
        primary.origin = narrow(widen(center) + distance * u);
        primary.direction = narrow((-std::sqrt(1 - sin_a * sin_a)) * u + sin_a * e);
        SurfaceHit hit;
        // Draw the spawn direction's numbers whether or not the primary hits, so that rays of
        // one seed stay paired across offset methods.
        const double cos_t = 0.05 + 0.95 * rng.uniform(),
                     phi = 2.0 * 3.14159265358979 * rng.uniform();
        if (!accel.intersect(primary, hit)) {
            ++row.primary_misses;
            continue;
        }
        const Vec3 n = hit.geometric_normal;  // outward: primary rays arrive from outside
        const Vec3 side = c.kind == SpawnKind::Reflection ? n : -n;
        Vec3 origin = hit.position;
        if (c.offset == OffsetMethod::FixedEpsilon) origin = hit.position + kFixedOffset * side;
        if (c.offset == OffsetMethod::PositionScaled) origin = scaled(hit, side);
        if (!all_finite(n) || !all_finite(origin)) {
            // The hit point rounded onto the centre (a sphere below the coordinates' ulp): no
            // normal, nothing to spawn. Embree must not see the NaN ray (Debian's build asserts).
            ++row.degenerate;
            continue;
        }
        const Vec3 helper = std::fabs(side.x) < 0.6f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
        const Vec3 t1 = glm::normalize(glm::cross(side, helper)), t2 = glm::cross(side, t1);
        const auto sin_t = static_cast<float>(std::sqrt(1.0 - cos_t * cos_t));
        Ray spawned;
        spawned.origin = origin;
        spawned.direction = glm::normalize(static_cast<float>(cos_t) * side +
                                           sin_t * (static_cast<float>(std::cos(phi)) * t1 +
                                                    static_cast<float>(std::sin(phi)) * t2));
        SurfaceHit second;
        const bool again = accel.intersect(spawned, second);
        // How far the offset moved the origin off the shading point, in radii.
        row.max_offset_radii = std::max(
            row.max_offset_radii, double(glm::length(spawned.origin - hit.position) / radius));
        if (c.kind == SpawnKind::Reflection) {
            if (again) ++row.self_hits;  // a convex surface is never met again leaving outward
            continue;
        }
        // Refraction: the ray must cross the interior and leave through the far side, where
        // the exact (long double) solution of this very spawned ray puts its larger root.
        const Reference ref = solve_reference(widen(spawned.origin), widen(spawned.direction),
                                              widen(center), LD(radius));
        const LD exit = ref.has_roots ? ref.far_root : 0;
        if (!(exit > 0)) {
            ++row.leaks;  // the offset put the origin outside, past the far side
        } else if (!again) {
            ++row.leaks;
        } else if (!(LD(second.t) >= 0.5L * exit)) {
            ++row.self_hits;
        } else if (std::fabs(LD(second.t) - exit) > 1e-3L * exit) {
            ++row.wrong_far;
        }
    }
    const int counted = row.rays - row.primary_misses;
    row.failure_rate =
        counted > 0
            ? double(row.self_hits + row.leaks + row.wrong_far + row.degenerate) / double(counted)
            : 0.0;
    return row;
}

AccelOptions offset_accel_options(SphereMath math) {
    AccelOptions o;
    o.spheres.method = SphereMethod::User;  // the renderer's default path
    o.sphere_math = math;
    return o;
}

}  // namespace

OffsetRow run_offset_case(const OffsetCase& c, const OffsetFunction& scaled) {
    check_offset_case(c, scaled);
    Scene scene;
    const Vec3 center = narrow(study_center(c.center_magnitude));
    const auto radius = static_cast<float>(c.radius);
    scene.shapes.of<Sphere>().push_back(Sphere{center, radius, 0});
    const Accel accel(scene, offset_accel_options(c.math));
    return run_offset_case_with(c, accel, center, radius, scaled);
}

std::vector<OffsetRow> run_offset_sweep(const OffsetConfig& c, const OffsetFunction& scaled) {
    std::vector<OffsetRow> rows;
    uint32_t index = 0;
    for (double radius : c.radii) {
        for (double magnitude : c.magnitudes) {
            // One Accel per sphere, shared by its configurations.
            Scene scene;
            const Vec3 center = narrow(study_center(magnitude));
            scene.shapes.of<Sphere>().push_back(Sphere{center, static_cast<float>(radius), 0});
            const Accel accel(scene, offset_accel_options(c.math));
            for (double distance : c.distance_ratios) {
                const uint32_t seed = c.seed + 7919u * index++;
                for (SpawnKind kind : {SpawnKind::Reflection, SpawnKind::Refraction}) {
                    for (OffsetMethod offset : {OffsetMethod::None, OffsetMethod::FixedEpsilon,
                                                OffsetMethod::PositionScaled}) {
                        OffsetCase oc;
                        oc.radius = radius;
                        oc.center_magnitude = magnitude;
                        oc.distance_ratio = distance;
                        oc.offset = offset;
                        oc.kind = kind;
                        oc.math = c.math;
                        oc.rays = c.rays;
                        oc.seed = seed;  // the same primary rays for every offset method
                        rows.push_back(run_offset_case_with(oc, accel, center,
                                                            static_cast<float>(radius), scaled));
                    }
                }
            }
        }
    }
    return rows;
}

void write_csv(std::ostream& out, const std::vector<StabilityRow>& rows) {
    const auto precision = out.precision();
    out << std::setprecision(9);
    out << "pattern,reference,distance_ratio,radius,center_magnitude,aim,seed,method,math,"
           "precision,rays,excluded,reference_hits,wrong_hits,wrong_misses,wrong_rate,both_hit,"
           "t_rel_median,t_rel_max,direct_mismatches,wrong_rim_max\n";
    for (const StabilityRow& r : rows) {
        const StabilityCase& c = r.config;
        out << ray_pattern_name(c.pattern) << ',' << reference_problem_name(c.reference) << ','
            << c.distance_ratio << ',' << c.radius << ',' << c.center_magnitude << ',' << c.aim
            << ',' << c.seed << ',' << r.method << ',' << r.math << ',' << r.precision << ','
            << r.rays << ',' << r.excluded << ',' << r.reference_hits << ',' << r.wrong_hits << ','
            << r.wrong_misses << ',' << r.wrong_rate << ',' << r.both_hit << ',' << r.t_rel_median
            << ',' << r.t_rel_max << ',' << r.direct_mismatches << ',' << r.wrong_rim_max << '\n';
    }
    out.precision(precision);
}

void write_csv(std::ostream& out, const std::vector<OffsetRow>& rows) {
    const auto precision = out.precision();
    out << std::setprecision(9);
    out << "radius,center_magnitude,distance_ratio,offset,kind,math,seed,rays,primary_misses,"
           "self_hits,leaks,wrong_far,degenerate,failure_rate,max_offset_radii\n";
    for (const OffsetRow& r : rows) {
        const OffsetCase& c = r.config;
        out << c.radius << ',' << c.center_magnitude << ',' << c.distance_ratio << ','
            << offset_method_name(c.offset) << ',' << spawn_kind_name(c.kind) << ','
            << sphere_math_name(c.math) << ',' << c.seed << ',' << r.rays << ',' << r.primary_misses
            << ',' << r.self_hits << ',' << r.leaks << ',' << r.wrong_far << ',' << r.degenerate
            << ',' << r.failure_rate << ',' << r.max_offset_radii << '\n';
    }
    out.precision(precision);
}

}  // namespace rayo
