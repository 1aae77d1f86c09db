#pragma once
// The sphere stability study (docs/stability.md): where each sphere method and precision fails,
// measured on deterministic random rays against a long-double reference, and how often spawned rays
// re-hit the sphere they leave for each origin-offset method. Tests, docs/stability.md and the CLI
// use it.
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "core/accel.h"
#include "core/sphere_method.h"

namespace rayo {

// One intersection method under study. BruteForce stands for the analytic formula called
// directly (intersect_sphere, what `bruteforce` runs per sphere); User, EmbreePoint and Mesh go
// through an Accel holding the one sphere. `math` matters for BruteForce and User only.
// `shape` other than Sphere studies the sphere written as a quadric (core/shapes/quadric.h,
// called directly): General = the `quadric` shape, x² + y² + z² − 2c·x + |c|² − r² with float
// coefficients in world coordinates; Ellipsoid = the `ellipsoid` shape (centre and radii kept
// apart). Both solve in double about the clip box's middle (core/shapes/clipped_quadric.h).
enum class StudyShape { Sphere, General, Ellipsoid };
struct StudyMethod {
    SphereMethod method = SphereMethod::BruteForce;
    SphereMath math = SphereMath::Stable;
    int mesh_level = 3;
    StudyShape shape = StudyShape::Sphere;
};

// "analytic", "user", "embree-point", "mesh:N".
std::string study_method_name(const StudyMethod& m);
// "seed"/"stable"/"double" for the analytic methods, "embree" for Embree's own intersectors.
std::string study_math_name(const StudyMethod& m);
// Analytic and user × seed/stable/double, embree-point, mesh:2, mesh:5.
std::vector<StudyMethod> default_study_methods();
// The quadric study (docs/stability.md, "Quadrics"): analytic/stable and analytic/double for
// comparison, then the sphere as a general `quadric` and as an `ellipsoid`.
std::vector<StudyMethod> quadric_study_methods();

enum class RayPattern {
    Disk,            // aimed uniformly over the projected disk out to (1 + aim) radii
    Grazing,         // every ray passes at exactly (1 + aim) radii from the centre (aim signed)
    SurfaceInward,   // origin on the sphere, moved `aim` radii along the normal; into the sphere
    SurfaceOutward,  // same origin, directions into the outer hemisphere
};
const char* ray_pattern_name(RayPattern p);

// What the reference solves. Rounded: the very float ray and sphere the methods get (measures
// their arithmetic). Intended: the geometry before rounding to float (measures what a float
// scene can represent at all: the breaking point of every method).
enum class ReferenceProblem { Rounded, Intended };
const char* reference_problem_name(ReferenceProblem r);

// One configuration of the accuracy study. The centre lies along (1, 0.5, −0.75)·magnitude plus
// a fraction of a float ulp (so that it is not exactly representable); ray origins lie at
// `distance_ratio` radii from the centre in uniformly random directions.
struct StabilityCase {
    RayPattern pattern = RayPattern::Disk;
    double distance_ratio = 10.0;  // |origin − centre| / radius (Disk, Grazing)
    double radius = 1.0;
    double center_magnitude = 0.0;  // largest |component| of the centre
    double aim = 0.25;              // see RayPattern
    ReferenceProblem reference = ReferenceProblem::Rounded;
    int rays = 2000;
    uint32_t seed = 1;
};

// Relative width of the tangent band: rays whose reference perpendicular distance p satisfies
// |p − r| ≤ kTangentBand·r are excluded from the wrong hit/miss count (counted in `excluded`).
constexpr double kTangentBand = 1e-6;

struct StabilityRow {
    StabilityCase config;
    std::string method;     // study_method_name
    std::string math;       // study_math_name
    std::string precision;  // "float" or "double"
    int rays = 0;
    int excluded = 0;           // in the tangent band of the reference
    int reference_hits = 0;     // among the rays not excluded
    int wrong_hits = 0;         // method hits, reference misses (not excluded)
    int wrong_misses = 0;       // method misses, reference hits (not excluded)
    double wrong_rate = 0.0;    // (wrong_hits + wrong_misses) / (rays − excluded)
    int both_hit = 0;           // rays (excluded or not) that both hit: the t statistics' sample
    double t_rel_median = 0.0;  // |t − t_ref| / t_ref over both_hit; 0 when both_hit == 0
    double t_rel_max = 0.0;
    // User rows: rays whose hit/miss or t (bit for bit) differ from the direct analytic call with
    // the same math (should be 0: Embree runs our code). −1 for the other methods.
    int direct_mismatches = -1;
    // Farthest wrong ray from the silhouette: max |p − r|/r over the wrong hits and misses (p the
    // reference perpendicular distance); 0 when none. The width of the band a method gets wrong.
    double wrong_rim_max = 0.0;
};

// Every method on one configuration: one row per method, in the order given.
std::vector<StabilityRow> run_stability_case(const StabilityCase& c,
                                             const std::vector<StudyMethod>& methods);

// The sweeps' grids; the defaults are the documented study (docs/stability.md), well under 10 s.
struct StabilityConfig {
    std::vector<StudyMethod> methods = default_study_methods();
    int rays = 2000;
    uint32_t seed = 20240611;
    // Distance sweep: unit sphere at the origin, Disk pattern with a 0.25-radius margin.
    std::vector<double> distance_ratios = {1,   3.16227766, 10,  31.6227766, 1e2, 316.227766,
                                           1e3, 3162.27766, 1e4, 31622.7766, 1e5, 316227.766,
                                           1e6, 3162277.66, 1e7};
    // Grazing sweep: unit sphere at the origin; rays pass at 1 ± each offset radii.
    std::vector<double> grazing_offsets = {1e-3, 1e-4, 1e-5, 1e-6};
    std::vector<double> grazing_distances = {10, 1e3};
    // Surface sweep: unit sphere, centre magnitudes; origins on the surface and ± these offsets.
    std::vector<double> surface_offsets = {0.0, 1e-3, -1e-3};
    std::vector<double> surface_magnitudes = {0.0, 1e2, 1e4};
    // Scale sweep (Disk at distance_ratio 10, both references): radii × centre magnitudes.
    std::vector<double> scale_radii = {1e-6, 1e-3, 1.0, 1e6};
    std::vector<double> scale_magnitudes = {0.0, 1e4, 1e6};
    // Breaking-point sweep (Disk at 10 radii, Intended reference): radii of these many float
    // ulps of the centre's largest coordinate, at breaking_magnitude.
    std::vector<double> breaking_ulps = {0.5, 1, 2, 4, 16, 256, 4096};
    double breaking_magnitude = 1e4;
};

std::vector<StabilityRow> run_distance_sweep(const StabilityConfig& c);
std::vector<StabilityRow> run_grazing_sweep(const StabilityConfig& c);
std::vector<StabilityRow> run_surface_sweep(const StabilityConfig& c);
std::vector<StabilityRow> run_scale_sweep(const StabilityConfig& c);
std::vector<StabilityRow> run_breaking_point_sweep(const StabilityConfig& c);
// All five sweeps, in that order.
std::vector<StabilityRow> run_stability_study(const StabilityConfig& c);
// The quadric study: the distance, grazing and scale sweeps of `c` with quadric_study_methods().
std::vector<StabilityRow> run_quadric_study(StabilityConfig c);

// --- spawned-ray self-intersection ---

enum class OffsetMethod {
    None,            // origin = the hit point
    FixedEpsilon,    // origin = hit point + kFixedOffset·n
    PositionScaled,  // rayo's offset_ray_origin (shading/integrators/whitted.h), passed in as a function
};
const char* offset_method_name(OffsetMethod m);
constexpr float kFixedOffset = 1e-4f;

enum class SpawnKind {
    Reflection,  // leaves outward: any hit of the same sphere is a self-intersection
    Refraction,  // leaves inward: must cross the interior and hit the far side
};
const char* spawn_kind_name(SpawnKind k);

// The origin-offset function under study: (hit, side normal) -> origin. shading/ provides
// rayo::offset_ray_origin; core cannot name it (core knows nothing of shading,
// docs/architecture.md).
using OffsetFunction = std::function<Vec3(const SurfaceHit&, const Vec3&)>;

// One configuration: camera-like primary rays from `distance_ratio` radii hit the sphere (aimed
// within 0.9 radii of its centre) through Accel (user geometry, `math`), the shading hit is
// SurfaceHit as the renderer sees it (float, re-projected), and one ray per primary hit is
// spawned with directions at least ~3° off the tangent plane (cos θ uniform in [0.05, 1]).
struct OffsetCase {
    double radius = 1.0;
    double center_magnitude = 0.0;
    double distance_ratio = 4.0;
    OffsetMethod offset = OffsetMethod::PositionScaled;
    SpawnKind kind = SpawnKind::Reflection;
    SphereMath math = SphereMath::Stable;
    int rays = 2000;
    uint32_t seed = 1;
};

struct OffsetRow {
    OffsetCase config;
    int rays = 0;
    int primary_misses = 0;  // primary rays that missed (left out of the rates)
    int self_hits = 0;  // reflection: any hit; refraction: a hit short of half the exit distance
    // Refraction: no hit, or the origin already outside past the far side. The exit distance is
    // the larger root of the spawned ray itself, solved exactly (long double).
    int leaks = 0;
    int wrong_far = 0;   // refraction: a hit past half the exit distance, off by more than 0.1%
    int degenerate = 0;  // non-finite hit normal or spawned origin: nothing can be traced
    // (self_hits + leaks + wrong_far + degenerate) / (rays − primary_misses)
    double failure_rate = 0.0;
    double max_offset_radii = 0.0;  // largest |spawned origin − hit position| / radius
};

// Throws std::invalid_argument when c.offset is PositionScaled and `scaled` is empty.
OffsetRow run_offset_case(const OffsetCase& c, const OffsetFunction& scaled);

struct OffsetConfig {
    std::vector<double> radii = {1e-3, 1.0, 1e3};
    std::vector<double> magnitudes = {0.0, 1.0, 1e2, 1e3, 1e4, 1e5, 1e6};
    std::vector<double> distance_ratios = {4.0};
    SphereMath math = SphereMath::Stable;
    int rays = 2000;
    uint32_t seed = 20240611;
};

// Every radius × magnitude × distance × offset method × spawn kind.
std::vector<OffsetRow> run_offset_sweep(const OffsetConfig& c, const OffsetFunction& scaled);

// CSV: a header line, then one line per row (numbers with 9 significant digits).
void write_csv(std::ostream& out, const std::vector<StabilityRow>& rows);
void write_csv(std::ostream& out, const std::vector<OffsetRow>& rows);

}  // namespace rayo
