// Pins what the sphere stability study (bench/lab/sphere_stability.h, docs/stability.md) finds:
// where the default stable float form stays exact, where the seed form fails, how far double goes,
// the spawned-ray offsets, and the breaking point that defeats every method.
#include "bench/lab/sphere_stability.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "core/shapes/icosphere.h"
#include "shading/integrators/whitted.h"

namespace rayo {
namespace {

const OffsetFunction kRayoOffset = [](const SurfaceHit& hit, const Vec3& side) {
    return offset_ray_origin(hit, side);
};

StabilityRow run_one(const StabilityCase& c, SphereMethod method, SphereMath math, int level = 0) {
    return run_stability_case(c, {StudyMethod{method, math, level}}).at(0);
}

StabilityCase disk_at(double distance_ratio, uint32_t seed = 11) {
    StabilityCase c;
    c.pattern = RayPattern::Disk;
    c.distance_ratio = distance_ratio;
    c.rays = 2000;
    c.seed = seed;
    return c;
}

TEST(StabilityDefault, StableFloatIsExactUpToDocumentedDistance) {
    // docs/stability.md: at most 1 wrong in 2000 rays up to distance/radius 1e4 (0 for this
    // seed), t within a few ulps.
    for (double d : {3.0, 10.0, 100.0, 1e3, 3e3, 1e4}) {
        const StabilityRow row = run_one(disk_at(d), SphereMethod::BruteForce, SphereMath::Stable);
        EXPECT_EQ(row.wrong_hits + row.wrong_misses, 0) << "distance/radius " << d;
        EXPECT_GT(row.reference_hits, 1000) << d;  // the disk is hit (64% of its area + margin)
        EXPECT_LT(row.t_rel_max, 4e-6) << d;
        EXPECT_LT(row.t_rel_median, 3e-7) << d;
    }
    // Beyond the limit it degrades gradually (a band ~ε·distance wide around the silhouette).
    EXPECT_LT(run_one(disk_at(1e5), SphereMethod::BruteForce, SphereMath::Stable).wrong_rate,
              0.005);
    const StabilityRow far = run_one(disk_at(1e6), SphereMethod::BruteForce, SphereMath::Stable);
    EXPECT_LT(far.wrong_rate, 0.03);
    EXPECT_GT(run_one(disk_at(1e7), SphereMethod::BruteForce, SphereMath::Stable).wrong_rate, 0.05);
}

TEST(StabilityDefault, WrongRaysLieWithinEpsilonTimesDistanceOfTheRim) {
    // The error model behind the limit and the auto rule: the stable float form misjudges only
    // rays within ~ε·distance (world units) of the silhouette, whatever the distance.
    constexpr double kEpsilon = 1.1920929e-7;
    int wrong = 0;
    for (double d : {1e3, 1e4, 1e5, 1e6}) {
        for (uint32_t seed : {1u, 2u, 3u}) {
            const StabilityRow row =
                run_one(disk_at(d, seed), SphereMethod::BruteForce, SphereMath::Stable);
            EXPECT_LE(row.wrong_rim_max, 2.0 * kEpsilon * d) << d << " seed " << seed;
            EXPECT_LE(row.wrong_hits + row.wrong_misses, 2e-8 * d * row.rays + 2) << d;
            wrong += row.wrong_hits + row.wrong_misses;
        }
        // The seed form's band is far wider: |f|² − r² cancels, an error of ~ε·(distance/r)²
        // radii (until it covers the whole disk).
        if (d <= 1e4) {
            const StabilityRow seed =
                run_one(disk_at(d), SphereMethod::BruteForce, SphereMath::Seed);
            EXPECT_GT(seed.wrong_rim_max, 20.0 * kEpsilon * d) << d;
        }
    }
    EXPECT_GT(wrong, 0);  // the band is real: the sample does find rays in it
}

TEST(StabilitySeed, FailureOnsetBetween1e2And1e4) {
    EXPECT_LT(run_one(disk_at(100.0), SphereMethod::BruteForce, SphereMath::Seed).wrong_rate,
              0.002);
    const StabilityRow at_1e3 = run_one(disk_at(1e3), SphereMethod::BruteForce, SphereMath::Seed);
    EXPECT_GT(at_1e3.wrong_rate, 0.02);
    EXPECT_LT(at_1e3.wrong_rate, 0.15);
    EXPECT_GT(at_1e3.t_rel_max, 1e-4);  // vs < 4e-6 for the stable form
    EXPECT_GT(run_one(disk_at(1e4), SphereMethod::BruteForce, SphereMath::Seed).wrong_rate, 0.35);
}

TEST(StabilityDouble, CleanFurtherOutThanFloat) {
    for (double d : {1e4, 1e5}) {
        const StabilityRow row = run_one(disk_at(d), SphereMethod::BruteForce, SphereMath::Double);
        EXPECT_EQ(row.wrong_hits + row.wrong_misses, 0) << d;
        EXPECT_LT(row.t_rel_max, 2e-7) << d;  // rounding t to float
    }
    const StabilityRow dbl = run_one(disk_at(1e6), SphereMethod::BruteForce, SphereMath::Double);
    const StabilityRow flt = run_one(disk_at(1e6), SphereMethod::BruteForce, SphereMath::Stable);
    EXPECT_LT(dbl.wrong_rate, 0.005);
    EXPECT_LT(dbl.wrong_rate, flt.wrong_rate);
}

StabilityRow run_shape(const StabilityCase& c, StudyShape shape) {
    return run_stability_case(c,
                              {StudyMethod{SphereMethod::BruteForce, SphereMath::Double, 0, shape}})
        .at(0);
}

TEST(StabilityQuadric, EllipsoidIsCleanAtEveryDistanceOfTheSweep) {
    // docs/stability.md, "Quadrics": the named form solves in double about the middle of its box,
    // so nothing cancels even at 1e7 radii, where the double sphere (solved about the ray's
    // origin) already misjudges rays.
    for (double d : {3.0, 1e3, 1e5, 1e6, 1e7}) {
        const StabilityRow row = run_shape(disk_at(d), StudyShape::Ellipsoid);
        EXPECT_EQ(row.wrong_hits + row.wrong_misses, 0) << d;
        EXPECT_GT(row.reference_hits, 1000) << d;
        EXPECT_LT(row.t_rel_max, 2e-7) << d;  // rounding t to float
    }
    EXPECT_GT(run_one(disk_at(1e7), SphereMethod::BruteForce, SphereMath::Double).wrong_rate, 0.01);
}

TEST(StabilityQuadric, WorldCoefficientsLoseSmallShapesFarFromTheOrigin) {
    // The general quadric's coefficients are world-space: a sphere of radius r at distance M
    // from the origin has J = M² − r², and r² drowns in J's rounding once r² < ε_double·M². At
    // the origin it matches the ellipsoid; at r = 1 and M = 1e4 too; at r = 1e-3 and M = 1e6
    // it fails where the ellipsoid (centre kept apart) does not.
    StabilityCase c = disk_at(10.0);
    EXPECT_EQ(run_shape(c, StudyShape::General).wrong_rate, 0.0);
    c.center_magnitude = 1e4;
    EXPECT_EQ(run_shape(c, StudyShape::General).wrong_rate, 0.0);
    c.radius = 1e-3;
    c.center_magnitude = 1e6;
    EXPECT_GT(run_shape(c, StudyShape::General).wrong_rate, 0.1);
    EXPECT_EQ(run_shape(c, StudyShape::Ellipsoid).wrong_rate, 0.0);
}

TEST(StabilityUser, EmbreeUserGeometryGivesTheDirectCallsNumbers) {
    const std::vector<StudyMethod> users = {{SphereMethod::User, SphereMath::Seed, 0},
                                            {SphereMethod::User, SphereMath::Stable, 0},
                                            {SphereMethod::User, SphereMath::Double, 0}};
    std::vector<StabilityCase> cases = {disk_at(10.0), disk_at(1e4), disk_at(1e7)};
    StabilityCase grazing = disk_at(1e3);
    grazing.pattern = RayPattern::Grazing;
    grazing.aim = -1e-5;
    cases.push_back(grazing);
    for (const StabilityCase& c : cases) {
        for (const StabilityRow& row : run_stability_case(c, users)) {
            EXPECT_EQ(row.direct_mismatches, 0) << row.math << " at " << c.distance_ratio;
        }
    }
}

TEST(StabilityEmbreePoint, ExactToFloatUpTo1e5) {
    for (double d : {10.0, 1e3, 1e5}) {
        const StabilityRow row = run_one(disk_at(d), SphereMethod::EmbreePoint, SphereMath::Stable);
        EXPECT_EQ(row.wrong_hits + row.wrong_misses, 0) << d;
        EXPECT_LT(row.t_rel_max, 1e-6) << d;
    }
}

TEST(StabilityMesh, InscribedFacetsMissTheSilhouetteAndShortenT) {
    const StabilityRow coarse = run_one(disk_at(10.0), SphereMethod::Mesh, SphereMath::Stable, 2);
    const StabilityRow fine = run_one(disk_at(10.0), SphereMethod::Mesh, SphereMath::Stable, 5);
    EXPECT_EQ(coarse.wrong_hits, 0);  // the mesh lies inside the sphere
    EXPECT_GT(coarse.wrong_misses, 0);
    EXPECT_LE(fine.wrong_misses, coarse.wrong_misses);
    EXPECT_GT(coarse.t_rel_max, 10 * fine.t_rel_max);
    // The t error stays within a few facet depths (more near the rim, where rays are oblique).
    EXPECT_LT(fine.t_rel_max, 8 * kIcosphereMaxDepth[5]);
    // Rays passing just inside the rim miss the coarse mesh almost always.
    StabilityCase rim = disk_at(10.0);
    rim.pattern = RayPattern::Grazing;
    rim.aim = -1e-3;
    EXPECT_GT(run_one(rim, SphereMethod::Mesh, SphereMath::Stable, 2).wrong_rate, 0.9);
}

TEST(StabilityGrazing, StableFloatResolvesTheTangentAt10Radii) {
    StabilityCase c = disk_at(10.0);
    c.pattern = RayPattern::Grazing;
    for (double aim : {1e-3, -1e-3, 1e-4, -1e-4, 1e-5, -1e-5, 1e-6, -1e-6}) {
        c.aim = aim;
        const StabilityRow row = run_one(c, SphereMethod::BruteForce, SphereMath::Stable);
        EXPECT_EQ(row.wrong_hits + row.wrong_misses, 0) << aim;
        // Rays aimed at 1 ± 1e-6 fall partly in the excluded band; nothing else does.
        if (std::fabs(aim) > 1e-5) {
            EXPECT_EQ(row.excluded, 0) << aim;
        }
    }
    c.distance_ratio = 1e3;
    c.aim = -1e-3;
    EXPECT_GT(run_one(c, SphereMethod::BruteForce, SphereMath::Seed).wrong_rate, 0.5);
    EXPECT_EQ(run_one(c, SphereMethod::BruteForce, SphereMath::Stable).wrong_rate, 0.0);
    c.aim = -1e-5;  // inside ε·distance of the rim: float loses the tangent, double does not
    EXPECT_GT(run_one(c, SphereMethod::BruteForce, SphereMath::Stable).wrong_rate, 0.03);
    EXPECT_EQ(run_one(c, SphereMethod::BruteForce, SphereMath::Double).wrong_rate, 0.0);
}

TEST(StabilitySurface, FloatCannotTellTheSideOfAnOriginOnTheSurface) {
    StabilityCase c = disk_at(10.0);
    c.pattern = RayPattern::SurfaceOutward;
    c.aim = 0.0;
    // The float origin lies a rounding error inside or outside: an outward ray then has (or
    // not) a tiny root that float cannot resolve; double can.
    EXPECT_GT(run_one(c, SphereMethod::BruteForce, SphereMath::Stable).wrong_rate, 0.1);
    EXPECT_EQ(run_one(c, SphereMethod::BruteForce, SphereMath::Double).wrong_rate, 0.0);
    c.aim = 1e-3;  // just off the surface, outside: every analytic form is right
    EXPECT_EQ(run_one(c, SphereMethod::BruteForce, SphereMath::Seed).wrong_rate, 0.0);
    EXPECT_EQ(run_one(c, SphereMethod::BruteForce, SphereMath::Stable).wrong_rate, 0.0);
}

TEST(StabilityBreakingPoint, RadiusOfTwoUlpsOfTheCentreDefeatsEveryMethod) {
    const float ulp = std::nextafter(1e4f, 2e4f) - 1e4f;
    StabilityCase c = disk_at(10.0);
    c.center_magnitude = 1e4;
    c.reference = ReferenceProblem::Intended;
    std::vector<StudyMethod> methods = default_study_methods();
    c.radius = 2.0 * ulp;
    for (const StabilityRow& row : run_stability_case(c, methods)) {
        EXPECT_GT(row.wrong_rate, 0.08) << row.method << "/" << row.math;
    }
    // Far from that scale every analytic method (double included) is right again.
    c.radius = 4096.0 * ulp;
    for (const StabilityRow& row : run_stability_case(c, methods)) {
        if (row.method.rfind("mesh", 0) == 0) continue;
        EXPECT_LT(row.wrong_rate, 0.005) << row.method << "/" << row.math;
    }
    // Against the float-rounded problem itself, the stable and double forms are still exact:
    // the failure is the representation, not the arithmetic.
    c.radius = 2.0 * ulp;
    c.reference = ReferenceProblem::Rounded;
    EXPECT_EQ(run_one(c, SphereMethod::BruteForce, SphereMath::Double).wrong_rate, 0.0);
}

OffsetRow offset_row(double radius, double magnitude, OffsetMethod offset, SpawnKind kind) {
    OffsetCase c;
    c.radius = radius;
    c.center_magnitude = magnitude;
    c.offset = offset;
    c.kind = kind;
    c.rays = 1000;
    c.seed = 5;
    return run_offset_case(c, kRayoOffset);
}

TEST(StabilityOffset, PositionScaledNeverSelfIntersects) {
    for (double radius : {1e-3, 1.0, 1e3}) {
        for (double magnitude : {0.0, 1.0, 1e2, 1e3, 1e4, 1e6}) {
            if (radius < 1e-5 * magnitude) continue;  // below ~ulps of the position: see below
            for (SpawnKind kind : {SpawnKind::Reflection, SpawnKind::Refraction}) {
                const OffsetRow row =
                    offset_row(radius, magnitude, OffsetMethod::PositionScaled, kind);
                EXPECT_EQ(row.self_hits, 0) << radius << " at " << magnitude;
                EXPECT_EQ(row.primary_misses + row.degenerate, 0) << radius << " " << magnitude;
                if (kind == SpawnKind::Refraction && radius >= 1e-4 * magnitude) {
                    EXPECT_EQ(row.failure_rate, 0.0) << radius << " at " << magnitude;
                }
            }
        }
    }
}

TEST(StabilityOffset, FixedEpsilonFailsAtLargeMagnitudesAndNoneFailsOften) {
    for (SpawnKind kind : {SpawnKind::Reflection, SpawnKind::Refraction}) {
        EXPECT_EQ(offset_row(1.0, 1e3, OffsetMethod::FixedEpsilon, kind).self_hits, 0);
        EXPECT_GT(offset_row(1.0, 1e4, OffsetMethod::FixedEpsilon, kind).failure_rate, 0.3);
        EXPECT_GT(offset_row(1.0, 1e6, OffsetMethod::FixedEpsilon, kind).failure_rate, 0.3);
        EXPECT_GT(offset_row(1e3, 0.0, OffsetMethod::FixedEpsilon, kind).self_hits, 0);
        for (double magnitude : {0.0, 1.0, 1e3, 1e6}) {
            EXPECT_GT(offset_row(1.0, magnitude, OffsetMethod::None, kind).failure_rate, 0.05)
                << magnitude;
        }
    }
    // At 1e4 the fixed offset is below half an ulp: it does not move the origin at all.
    EXPECT_EQ(
        offset_row(1.0, 1e4, OffsetMethod::FixedEpsilon, SpawnKind::Reflection).max_offset_radii,
        0.0);
}

TEST(StabilityOffset, PositionScaledOffsetOutgrowsSpheresBelowAboutFortyUlps) {
    // eps = 1e-5·|P|: once it exceeds the diameter, a refracted ray starts outside, past the far
    // side, and never crosses the sphere (the offset's own breaking point).
    const OffsetRow row = offset_row(1.0, 1e6, OffsetMethod::PositionScaled, SpawnKind::Refraction);
    EXPECT_GT(row.max_offset_radii, 2.0);
    EXPECT_GT(row.leaks, 900);
    // A sphere smaller than the ulp of its position: hits round onto its centre. Accel then
    // faces the normal to the ray (finite, never NaN), but nothing spawned from it is right.
    const OffsetRow tiny =
        offset_row(1e-3, 1e6, OffsetMethod::PositionScaled, SpawnKind::Refraction);
    EXPECT_EQ(tiny.degenerate, 0);
    EXPECT_GT(tiny.failure_rate, 0.9);
}

TEST(StabilityStudy, DefaultStudyRowsAreCompleteAndWrittenAsCsv) {
    const StabilityConfig config;
    const std::vector<StabilityRow> rows = run_stability_study(config);
    const size_t methods = config.methods.size();
    const size_t cases = config.distance_ratios.size() +
                         2 * config.grazing_offsets.size() * config.grazing_distances.size() +
                         2 * config.surface_offsets.size() * config.surface_magnitudes.size() +
                         2 * config.scale_radii.size() * config.scale_magnitudes.size() +
                         config.breaking_ulps.size();
    ASSERT_EQ(rows.size(), cases * methods);
    for (const StabilityRow& row : rows) {
        EXPECT_EQ(row.rays, config.rays);
        EXPECT_TRUE(std::isfinite(row.t_rel_max) && std::isfinite(row.t_rel_median));
        EXPECT_LE(row.t_rel_median, row.t_rel_max);
        if (row.method == "user") {
            EXPECT_EQ(row.direct_mismatches, 0);
        }
    }
    const std::vector<OffsetRow> offsets = run_offset_sweep(OffsetConfig{}, kRayoOffset);
    EXPECT_EQ(offsets.size(), 3u * 7u * 1u * 2u * 3u);

    std::ostringstream csv;
    write_csv(csv, rows);
    std::istringstream lines(csv.str());
    std::string line;
    std::getline(lines, line);
    EXPECT_EQ(line.rfind("pattern,reference,distance_ratio,radius,", 0), 0u);
    const auto columns = std::count(line.begin(), line.end(), ',');
    size_t count = 0;
    while (std::getline(lines, line)) {
        EXPECT_EQ(std::count(line.begin(), line.end(), ','), columns) << line;
        ++count;
    }
    EXPECT_EQ(count, rows.size());

    // RAYO_STABILITY_CSV_DIR=dir writes the study's tables (docs/stability.md).
    if (const char* dir = std::getenv("RAYO_STABILITY_CSV_DIR")) {
        std::ofstream study(std::string(dir) + "/stability.csv");
        write_csv(study, rows);
        std::ofstream offset(std::string(dir) + "/offsets.csv");
        write_csv(offset, offsets);
        EXPECT_TRUE(study.good() && offset.good()) << dir;
    }
}

TEST(StabilityStudy, DeterministicForASeed) {
    StabilityCase c = disk_at(1e3, 99);
    const auto a = run_stability_case(c, default_study_methods());
    const auto b = run_stability_case(c, default_study_methods());
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].wrong_hits, b[i].wrong_hits);
        EXPECT_EQ(a[i].wrong_misses, b[i].wrong_misses);
        EXPECT_EQ(a[i].t_rel_max, b[i].t_rel_max);
    }
    std::ostringstream offsets;
    write_csv(offsets, std::vector<OffsetRow>{
                           offset_row(1.0, 1.0, OffsetMethod::None, SpawnKind::Reflection)});
    EXPECT_NE(offsets.str().find("none,reflection,stable"), std::string::npos);
}

TEST(StabilityStudy, RejectsBadConfigurations) {
    StabilityCase c;
    for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::infinity()}) {
        c.radius = bad;
        EXPECT_THROW(run_stability_case(c, default_study_methods()), std::invalid_argument);
    }
    c = StabilityCase{};
    c.distance_ratio = 0.5;
    EXPECT_THROW(run_stability_case(c, default_study_methods()), std::invalid_argument);
    OffsetCase o;
    o.offset = OffsetMethod::PositionScaled;
    EXPECT_THROW(run_offset_case(o, OffsetFunction{}), std::invalid_argument);
    o.radius = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(run_offset_case(o, kRayoOffset), std::invalid_argument);
}

}  // namespace
}  // namespace rayo
