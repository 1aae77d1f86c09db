// Tests of ray/sphere intersection (core/shapes/sphere.h, seed 000 eqs. [3]-[9]): the seed's worked
// examples in both SphereMath forms and both precisions, tangent/miss cases, the (tnear, tfar)
// window, and the accuracy of the stable form against the seed form far from the sphere.
#include "core/shapes/sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec3;

template <typename T>
struct Case {
    using V = glm::vec<3, T>;
    V origin, direction, center;
    T radius;
};

template <typename T>
class SphereWorkedExample : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(SphereWorkedExample, Scalars);

TYPED_TEST(SphereWorkedExample, OriginOutsideHitsTheNearRoot) {
    using T = TypeParam;
    using V = glm::vec<3, T>;
    // seed 000, worked example 1: R0 = (1,−2,−1), Rd = (1,2,4)/√21, Sc = (3,0,5), Sr = 3
    // -> t = 3.7435, P = (1.8169, −0.3662, 2.2676), n = (−0.3944, −0.1221, −0.9108)
    // (double-precision values: t = 3.743477, P = (1.816894, −0.366213, 2.267575)).
    const V origin(1, -2, -1), direction = glm::normalize(V(1, 2, 4)), center(3, 0, 5);
    const T radius = 3;
    for (SphereMath math : {SphereMath::Seed, SphereMath::Stable}) {
        SCOPED_TRACE(math == SphereMath::Seed ? "seed" : "stable");
        T t = -1;
        bool far_root = true;
        ASSERT_TRUE(intersect_sphere(math, origin, direction, center, radius, T(0),
                                     std::numeric_limits<T>::infinity(), t, far_root));
        EXPECT_NEAR(t, 3.7435, 1e-4);
        EXPECT_FALSE(far_root);
        const V p = origin + t * direction;
        expect_vec3(p, 1.8169, -0.3662, 2.2676, 1e-4);
        expect_vec3(sphere_normal(p, center, radius, far_root), -0.3944, -0.1221, -0.9108, 1e-4);
    }
}

TYPED_TEST(SphereWorkedExample, OriginInsideHitsTheFarRootWithFlippedNormal) {
    using T = TypeParam;
    using V = glm::vec<3, T>;
    // seed 000, worked example 2: R0 = (3,−2,2), Rd = (1,2,3)/√14, Sc = (4,1,3), Sr = 4
    // -> t0 = −0.812 rejected, t = t1 = 6.1573, P = (4.6456, 1.2912, 6.9368),
    // n = −(0.1614, 0.0728, 0.9842) (flipped: the origin is inside).
    const V origin(3, -2, 2), direction = glm::normalize(V(1, 2, 3)), center(4, 1, 3);
    const T radius = 4;
    for (SphereMath math : {SphereMath::Seed, SphereMath::Stable}) {
        SCOPED_TRACE(math == SphereMath::Seed ? "seed" : "stable");
        T t = -1;
        bool far_root = false;
        ASSERT_TRUE(intersect_sphere(math, origin, direction, center, radius, T(0),
                                     std::numeric_limits<T>::infinity(), t, far_root));
        EXPECT_NEAR(t, 6.1573, 1e-4);
        EXPECT_TRUE(far_root);
        const V p = origin + t * direction;
        expect_vec3(p, 4.6456, 1.2912, 6.9368, 1e-4);
        expect_vec3(sphere_normal(p, center, radius, far_root), -0.1614, -0.0728, -0.9842, 1e-4);
        // With tnear below t0 = −0.812 the near root is accepted instead (and is not flipped).
        ASSERT_TRUE(intersect_sphere(math, origin, direction, center, radius, T(-1),
                                     std::numeric_limits<T>::infinity(), t, far_root));
        EXPECT_NEAR(t, -0.8120, 1e-4);
        EXPECT_FALSE(far_root);
    }
}

TYPED_TEST(SphereWorkedExample, TangentAndMissingRaysMiss) {
    using T = TypeParam;
    using V = glm::vec<3, T>;
    const T inf = std::numeric_limits<T>::infinity();
    for (SphereMath math : {SphereMath::Seed, SphereMath::Stable}) {
        SCOPED_TRACE(math == SphereMath::Seed ? "seed" : "stable");
        T t = -1;
        bool far_root = false;
        // Tangent to the unit sphere at (0,1,0): D = 0 exactly, which seed 000 counts as a miss.
        EXPECT_FALSE(
            intersect_sphere(math, V(0, 1, -5), V(0, 0, 1), V(0), T(1), T(0), inf, t, far_root));
        // Passing 0.5 above it.
        EXPECT_FALSE(
            intersect_sphere(math, V(0, 1.5, -5), V(0, 0, 1), V(0), T(1), T(0), inf, t, far_root));
        // Sphere behind the origin: both roots (−6, −4) negative.
        EXPECT_FALSE(
            intersect_sphere(math, V(0, 0, 5), V(0, 0, 1), V(0), T(1), T(0), inf, t, far_root));
        // Just inside the tangent: hits, at t = 5 − √(1 − 0.99²) = 4.858933.
        ASSERT_TRUE(
            intersect_sphere(math, V(0, 0.99, -5), V(0, 0, 1), V(0), T(1), T(0), inf, t, far_root));
        EXPECT_NEAR(t, 5.0 - std::sqrt(1.0 - 0.99 * 0.99), 1e-5);
    }
}

TYPED_TEST(SphereWorkedExample, WindowSelectsTheRoot) {
    using T = TypeParam;
    using V = glm::vec<3, T>;
    const T inf = std::numeric_limits<T>::infinity();
    // Unit sphere at the origin, ray from (0,0,−5) along +z: roots t = 4 and t = 6, exact in
    // both forms (seed: B = −10, C = 24, D = 4; stable: b = −5, Δ = 1, c = 24, q = 6).
    const V origin(0, 0, -5), direction(0, 0, 1), center(0);
    for (SphereMath math : {SphereMath::Seed, SphereMath::Stable}) {
        SCOPED_TRACE(math == SphereMath::Seed ? "seed" : "stable");
        T t = -1;
        bool far_root = true;
        ASSERT_TRUE(
            intersect_sphere(math, origin, direction, center, T(1), T(0), inf, t, far_root));
        EXPECT_EQ(t, T(4));
        EXPECT_FALSE(far_root);
        // tfar before the near root: miss.
        EXPECT_FALSE(
            intersect_sphere(math, origin, direction, center, T(1), T(0), T(3.5), t, far_root));
        // The window is open: tfar = 4 excludes t = 4.
        EXPECT_FALSE(
            intersect_sphere(math, origin, direction, center, T(1), T(0), T(4), t, far_root));
        // tnear past the near root: the far root, flagged.
        ASSERT_TRUE(
            intersect_sphere(math, origin, direction, center, T(1), T(4.5), inf, t, far_root));
        EXPECT_EQ(t, T(6));
        EXPECT_TRUE(far_root);
        // tnear = 4 excludes t = 4 as well.
        ASSERT_TRUE(
            intersect_sphere(math, origin, direction, center, T(1), T(4), inf, t, far_root));
        EXPECT_EQ(t, T(6));
        // A window strictly between the roots, or past both: miss.
        EXPECT_FALSE(
            intersect_sphere(math, origin, direction, center, T(1), T(4.5), T(5.5), t, far_root));
        EXPECT_FALSE(
            intersect_sphere(math, origin, direction, center, T(1), T(6.5), inf, t, far_root));
        // The normal at the near root points back to the ray origin.
        const V n = sphere_normal(origin + T(4) * direction, center, T(1), false);
        EXPECT_EQ(n, V(0, 0, -1));
        EXPECT_EQ(sphere_normal(origin + T(6) * direction, center, T(1), true), V(0, 0, -1));
    }
}

// Double reference for the exact float ray (direction converted as stored, so not quite unit):
// solve A t² + 2 b t + c = 0, A = d·d, with the discriminant from the perpendicular distance.
// `delta` gets r² − (perpendicular distance)², the (scaled) discriminant.
bool reference_hit(const Vec3& origin_f, const Vec3& direction_f, const Vec3& center_f,
                   double radius, double& t_out, double& delta) {
    const DVec3 origin(origin_f), d(direction_f), center(center_f);
    const DVec3 f = origin - center;
    const double a = glm::dot(d, d), b = glm::dot(f, d);
    const DVec3 perpendicular = f - (b / a) * d;
    delta = radius * radius - glm::dot(perpendicular, perpendicular);
    if (!(delta > 0.0)) return false;
    const double t0 = (-b - std::sqrt(a * delta)) / a;
    if (!(t0 > 0.0)) return false;  // the origin is far outside in these tests
    t_out = t0;
    return true;
}

struct FarSphereStats {
    int rays = 0;
    int reference_hits = 0;
    int near_tangent = 0;  // |r² − p²| < 1e-2: hit/miss within float rounding of the inputs
    int stable_mismatches = 0;
    int stable_mismatches_off_tangent = 0;
    int seed_mismatches = 0;
    double stable_max_relative_error = 0.0;
};

// `rays` rays from within a unit ball around the origin toward points within `spread` radii
// of the centre of a unit sphere `distance` away in a random direction.
FarSphereStats measure_far_sphere(double distance, double spread, int rays, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    auto random_in_ball = [&] {
        for (;;) {
            const DVec3 v(unit(rng), unit(rng), unit(rng));
            if (glm::length(v) <= 1.0) return v;
        }
    };
    auto random_unit = [&] {
        for (;;) {
            const DVec3 v = random_in_ball();
            if (glm::length(v) > 0.1) return glm::normalize(v);
        }
    };
    FarSphereStats stats;
    const float radius = 1.0f, inf = std::numeric_limits<float>::infinity();
    for (int i = 0; i < rays; ++i) {
        const Vec3 origin(random_in_ball());
        const Vec3 center(DVec3(origin) + distance * random_unit());
        const Vec3 target(DVec3(center) + spread * random_in_ball());
        const Vec3 direction = glm::normalize(target - origin);
        double t_ref = 0.0, delta = 0.0;
        const bool ref = reference_hit(origin, direction, center, radius, t_ref, delta);
        float t_stable = 0.0f, t_seed = 0.0f;
        bool far_root = false;
        const bool stable = intersect_sphere_stable(origin, direction, center, radius, 0.0f, inf,
                                                    t_stable, far_root);
        const bool seed_form =
            intersect_sphere_seed(origin, direction, center, radius, 0.0f, inf, t_seed, far_root);
        const bool near_tangent = std::abs(delta) < 1e-2;
        stats.rays++;
        stats.reference_hits += ref;
        stats.near_tangent += near_tangent;
        stats.stable_mismatches += stable != ref;
        stats.stable_mismatches_off_tangent += stable != ref && !near_tangent;
        stats.seed_mismatches += seed_form != ref;
        if (stable && ref) {
            stats.stable_max_relative_error = std::max(stats.stable_max_relative_error,
                                                       std::abs(double(t_stable) - t_ref) / t_ref);
        }
    }
    return stats;
}

// The numbers quoted below were measured with these seeds (std::mt19937, libstdc++).

TEST(SphereAccuracy, StableFormMatchesDoubleReferenceAtDistance1e4) {
    // Unit sphere 1e4 away, 10,000 rays aimed within 0.9 radius of its centre: every ray hits.
    // Measured: 0 hit/miss mismatches; max relative error of t 2.7e-7 (about 3 float ulps at
    // t = 1e4). Asserted: 1e-3 relative (the design's bound) and 1e-6.
    const FarSphereStats s = measure_far_sphere(1e4, 0.9, 10000, 20240501);
    EXPECT_EQ(s.reference_hits, 10000);
    EXPECT_EQ(s.stable_mismatches, 0);
    EXPECT_LT(s.stable_max_relative_error, 1e-3);
    EXPECT_LT(s.stable_max_relative_error, 1e-6);
}

TEST(SphereAccuracy, SeedFormLosesHitsAtDistance1e4) {
    // Same rays: in float the seed form's C = |f|² − r² ≈ 1e8 has an ulp of 8, so D = B² − 4C
    // (true value ≤ 4) is rounding noise. Measured: 7,380 of 10,000 (73.8%) hit/miss mismatches,
    // all of them lost hits. Asserted: > 50% (the design's "> 1%" and "~45%" both hold).
    const FarSphereStats s = measure_far_sphere(1e4, 0.9, 10000, 20240501);
    EXPECT_GT(s.seed_mismatches, s.rays / 100);
    EXPECT_GT(s.seed_mismatches, 5000);
}

TEST(SphereAccuracy, HitsAndMissesAtDistance1e4) {
    // Rays within 1.5 radii of the centre: 5,880 of 10,000 hit in the double reference.
    // Measured: seed form 5,289 mismatches (52.9%; the design notes quote ~45%); stable form 2,
    // both within 1e-2 of tangency (|r² − p²|), where float rounding of the ray itself decides.
    const FarSphereStats s = measure_far_sphere(1e4, 1.5, 10000, 7);
    EXPECT_GT(s.reference_hits, 5000);
    EXPECT_LT(s.reference_hits, 7000);
    EXPECT_GT(s.seed_mismatches, 4000);
    EXPECT_EQ(s.stable_mismatches_off_tangent, 0);
    EXPECT_LE(s.stable_mismatches, s.near_tangent);
    EXPECT_LT(s.stable_mismatches, 10);
    EXPECT_LT(s.stable_max_relative_error, 1e-5);
}

TEST(SphereAccuracy, HitsAndMissesAtDistance1e3) {
    // Distance/radius 1e3, rays within 1.5 radii of the centre (5,881 reference hits).
    // Measured: seed form 557 mismatches (5.6%; the design notes say ~1%, which matches our
    // near-centre rays: 26 of 10,000 within 0.9 radii); stable form 0, max relative error of t
    // 1.0e-6 (near-tangent rays, where t is ill-conditioned). Asserted with margin.
    const FarSphereStats s = measure_far_sphere(1e3, 1.5, 10000, 7);
    EXPECT_GT(s.reference_hits, 5000);
    EXPECT_LT(s.reference_hits, 7000);
    EXPECT_GT(s.seed_mismatches, 200);
    EXPECT_EQ(s.stable_mismatches_off_tangent, 0);
    EXPECT_LE(s.stable_mismatches, 2);
    EXPECT_LT(s.stable_max_relative_error, 1e-5);
}

// The Shape interface of the sphere: every crossing of the line, sorted, entering then leaving
// (what CSG by intervals needs), and the spherical parameterization.
TEST(SphereShape, CrossingsOfTheWholeLineSortedEnteringThenLeaving) {
    const Sphere s{Vec3(0.0f), 1.0f, 0};
    ShapeCrossing c[kMaxShapeCrossings];
    ASSERT_EQ(s.crossings(Vec3(0, 0, -5), Vec3(0, 0, 1), c), 2);
    EXPECT_FLOAT_EQ(c[0].t, 4.0f);
    EXPECT_TRUE(c[0].entering);
    EXPECT_FLOAT_EQ(c[1].t, 6.0f);
    EXPECT_FALSE(c[1].entering);
    // From inside: the entering crossing lies behind the origin (negative t).
    ASSERT_EQ(s.crossings(Vec3(0, 0, 0.5f), Vec3(0, 0, 1), c), 2);
    EXPECT_FLOAT_EQ(c[0].t, -1.5f);
    EXPECT_FLOAT_EQ(c[1].t, 0.5f);
    EXPECT_EQ(s.crossings(Vec3(0, 2, -5), Vec3(0, 0, 1), c), 0);
}

TEST(SphereShape, ParameterizationAtKnownPoints) {
    const Sphere s{Vec3(1.0f, 2.0f, 3.0f), 2.0f, 0};
    SurfaceHit hit;
    s.parameterization(s.center + Vec3(0, 0, 2), hit);  // on +z: φ = 0, θ = π/2
    EXPECT_NEAR(hit.uv.x, 0.5f, 1e-6f);
    EXPECT_NEAR(hit.uv.y, 0.5f, 1e-6f);
    EXPECT_NEAR(hit.dpdu.x, 2.0f * kPi * 2.0f, 1e-5f);  // 2π·r along +x
    EXPECT_NEAR(glm::length(hit.dpdu - Vec3(hit.dpdu.x, 0, 0)), 0.0f, 1e-6f);
    s.parameterization(s.center + Vec3(0, 2, 0), hit);  // the pole: v = 0
    EXPECT_NEAR(hit.uv.y, 0.0f, 1e-6f);
    s.parameterization(s.center + Vec3(2, 0, 0), hit);  // on +x: φ = π/2, u = 3/4
    EXPECT_NEAR(hit.uv.x, 0.75f, 1e-6f);
    EXPECT_NEAR(glm::dot(hit.dpdu, Vec3(1, 0, 0)), 0.0f, 1e-5f);  // tangent
}

}  // namespace
}  // namespace rayo
