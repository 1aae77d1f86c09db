// Tests of the NFF open cone/cylinder intersection (core/shapes/cone.h): analytic hit distances and
// normals for cylinders and cones, no caps, the axial segment limits, and rays from inside.
#include "core/shapes/cone.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec_near;

constexpr float kInf = std::numeric_limits<float>::infinity();

// Cylinder of radius 1 around the y axis, 0 <= y <= 2.
Cone unit_cylinder() {
    Cone c;
    c.base = Vec3(0.0f);
    c.base_radius = 1.0f;
    c.apex = Vec3(0.0f, 2.0f, 0.0f);
    c.apex_radius = 1.0f;
    return c;
}

// Cone with its base circle (radius 1) at y = 0 and its apex (radius 0) at y = 1: the surface
// x² + z² = (1 − y)².
Cone pointed_cone() {
    Cone c;
    c.base = Vec3(0.0f);
    c.base_radius = 1.0f;
    c.apex = Vec3(0.0f, 1.0f, 0.0f);
    c.apex_radius = 0.0f;
    return c;
}

TEST(Cone, CylinderHitFromTheSide) {
    float t = -1.0f;
    Vec3 n(0.0f);
    // Head-on from x = −5 at mid height: the wall x = −1 is 4 away, normal −x.
    ASSERT_TRUE(intersect_cone(unit_cylinder(), Vec3(-5.0f, 1.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f),
                               0.0f, kInf, t, n));
    EXPECT_NEAR(t, 4.0f, 1e-6f);
    expect_vec_near(n, Vec3(-1.0f, 0.0f, 0.0f), 1e-6f);
    // Off-centre by z = 0.5: the wall is at x = −√(1 − 0.25) = −0.866025, so t = 5 − 0.866025 =
    // 4.133975, and the normal is radial, (−0.866025, 0, 0.5).
    ASSERT_TRUE(intersect_cone(unit_cylinder(), Vec3(-5.0f, 1.5f, 0.5f), Vec3(1.0f, 0.0f, 0.0f),
                               0.0f, kInf, t, n));
    EXPECT_NEAR(t, 5.0f - std::sqrt(0.75f), 1e-5f);
    expect_vec_near(n, Vec3(-std::sqrt(0.75f), 0.0f, 0.5f), 1e-5f);
    // The window (tnear, tfar) applies: tfar before the wall misses.
    EXPECT_FALSE(intersect_cone(unit_cylinder(), Vec3(-5.0f, 1.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f),
                                0.0f, 3.9f, t, n));
    // tnear past the near wall: the far wall at t = 6, whose outward normal is +x.
    ASSERT_TRUE(intersect_cone(unit_cylinder(), Vec3(-5.0f, 1.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f),
                               4.5f, kInf, t, n));
    EXPECT_NEAR(t, 6.0f, 1e-5f);
    expect_vec_near(n, Vec3(1.0f, 0.0f, 0.0f), 1e-6f);
}

TEST(Cone, TiltedCylinderHitAtTheAnalyticDistance) {
    // A cylinder with a general axis: construct the hit point P = base + s·a + r·u (u ⟂ a) and
    // shoot at it from P + k·u along −u, so t = k and the normal is u.
    const Vec3 axis = glm::normalize(Vec3(1.0f, 2.0f, -0.5f));
    const Vec3 u = glm::normalize(glm::cross(axis, Vec3(0.0f, 0.0f, 1.0f)));
    Cone c;
    c.base = Vec3(3.0f, -1.0f, 2.0f);
    c.base_radius = 0.75f;
    c.apex = c.base + 5.0f * axis;
    c.apex_radius = 0.75f;
    const Vec3 p = c.base + 2.0f * axis + 0.75f * u;
    float t = -1.0f;
    Vec3 n(0.0f);
    ASSERT_TRUE(intersect_cone(c, p + 3.0f * u, -u, 0.0f, kInf, t, n));
    EXPECT_NEAR(t, 3.0f, 1e-5f);
    expect_vec_near(n, u, 1e-5f);
    EXPECT_NEAR(glm::dot(n, axis), 0.0f, 1e-6f);  // radial: perpendicular to the axis
}

TEST(Cone, PointedConeHitWithSlantedNormal) {
    float t = -1.0f;
    Vec3 n(0.0f);
    // At y = 0.5 the radius is 0.5: from x = −5 the wall is 4.5 away. The outward normal is the
    // gradient of x² + z² − (1 − y)², (2x, 2(1 − y), 2z) ∝ (−0.5, 0.5, 0) -> (−1, 1, 0)/√2.
    ASSERT_TRUE(intersect_cone(pointed_cone(), Vec3(-5.0f, 0.5f, 0.0f), Vec3(1.0f, 0.0f, 0.0f),
                               0.0f, kInf, t, n));
    EXPECT_NEAR(t, 4.5f, 1e-6f);
    const float h = std::sqrt(0.5f);
    expect_vec_near(n, Vec3(-h, h, 0.0f), 1e-6f);
    // At y = 0.75 (radius 0.25) from z = +5 along −z: t = 4.75; gradient (0, 2·0.25, 2·0.25)
    // -> (0, 1, 1)/√2.
    ASSERT_TRUE(intersect_cone(pointed_cone(), Vec3(0.0f, 0.75f, 5.0f), Vec3(0.0f, 0.0f, -1.0f),
                               0.0f, kInf, t, n));
    EXPECT_NEAR(t, 4.75f, 1e-6f);
    expect_vec_near(n, Vec3(0.0f, h, h), 1e-6f);
    // Straight down from (0.5, 5, 0): the double cone x² + z² = (1 − y)² is met at y = 1.5
    // (the other nappe, beyond the apex: rejected) and at y = 0.5 (t = 4.5, the slanted wall,
    // gradient (1, 1, 0) -> (1, 1, 0)/√2).
    ASSERT_TRUE(intersect_cone(pointed_cone(), Vec3(0.5f, 5.0f, 0.0f), Vec3(0.0f, -1.0f, 0.0f),
                               0.0f, kInf, t, n));
    EXPECT_NEAR(t, 4.5f, 1e-6f);
    expect_vec_near(n, Vec3(h, h, 0.0f), 1e-6f);
}

TEST(Cone, TruncatedConeRadiusVariesLinearly) {
    // Base radius 2 at y = 0, apex radius 1 at y = 4: r(y) = 2 − y/4. At y = 2, r = 1.5.
    Cone c;
    c.base = Vec3(0.0f);
    c.base_radius = 2.0f;
    c.apex = Vec3(0.0f, 4.0f, 0.0f);
    c.apex_radius = 1.0f;
    float t = -1.0f;
    Vec3 n(0.0f);
    ASSERT_TRUE(
        intersect_cone(c, Vec3(10.0f, 2.0f, 0.0f), Vec3(-1.0f, 0.0f, 0.0f), 0.0f, kInf, t, n));
    EXPECT_NEAR(t, 8.5f, 1e-5f);
    // Gradient of x² + z² − (2 − y/4)²: (2x, (2 − y/4)/2, 2z) = (3, 0.75, 0) -> (4, 1, 0)/√17.
    expect_vec_near(n, Vec3(4.0f, 1.0f, 0.0f) / std::sqrt(17.0f), 1e-6f);
}

TEST(Cone, RayAlongTheAxisMisses) {
    float t = -1.0f;
    Vec3 n(0.0f);
    // Open surfaces have no caps: a ray down the axis never meets the wall.
    EXPECT_FALSE(intersect_cone(unit_cylinder(), Vec3(0.0f, -5.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f),
                                0.0f, kInf, t, n));
    EXPECT_FALSE(intersect_cone(unit_cylinder(), Vec3(0.0f, 7.0f, 0.0f), Vec3(0.0f, -1.0f, 0.0f),
                                0.0f, kInf, t, n));
    // Parallel to the axis, inside the radius: also through both open ends.
    EXPECT_FALSE(intersect_cone(unit_cylinder(), Vec3(0.5f, -5.0f, 0.3f), Vec3(0.0f, 1.0f, 0.0f),
                                0.0f, kInf, t, n));
    // A truncated cone (radii 1 and 0.5) down its axis.
    Cone truncated = unit_cylinder();
    truncated.apex_radius = 0.5f;
    EXPECT_FALSE(intersect_cone(truncated, Vec3(0.0f, -5.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), 0.0f,
                                kInf, t, n));
}

TEST(Cone, HitsBeyondTheSegmentAreRejected) {
    float t = -1.0f;
    Vec3 n(0.0f);
    // Above (y = 3) and below (y = −1) the cylinder's segment 0 <= y <= 2: the infinite
    // cylinder would be hit, the segment is not.
    EXPECT_FALSE(intersect_cone(unit_cylinder(), Vec3(-5.0f, 3.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f),
                                0.0f, kInf, t, n));
    EXPECT_FALSE(intersect_cone(unit_cylinder(), Vec3(-5.0f, -1.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f),
                                0.0f, kInf, t, n));
    // Entering through the open top: the near root (x = −1 at y = 2.5) lies above the segment
    // and is skipped; the far root (x = +1 at y = 0.5, t = 3√2) is the hit, on the inside of
    // the wall, whose outward normal is +x.
    const Vec3 d = glm::normalize(Vec3(1.0f, -1.0f, 0.0f));
    ASSERT_TRUE(intersect_cone(unit_cylinder(), Vec3(-2.0f, 3.5f, 0.0f), d, 0.0f, kInf, t, n));
    EXPECT_NEAR(t, 3.0f * std::sqrt(2.0f), 1e-5f);
    expect_vec_near(n, Vec3(1.0f, 0.0f, 0.0f), 1e-5f);
    // The other nappe of the pointed cone (y > 1, where 1 − y < 0) is not part of the surface.
    EXPECT_FALSE(intersect_cone(pointed_cone(), Vec3(-5.0f, 1.5f, 0.0f), Vec3(1.0f, 0.0f, 0.0f),
                                0.0f, kInf, t, n));
    EXPECT_FALSE(intersect_cone(pointed_cone(), Vec3(-5.0f, -0.5f, 0.0f), Vec3(1.0f, 0.0f, 0.0f),
                                0.0f, kInf, t, n));
}

TEST(Cone, RayFromInsideHitsTheFarWall) {
    float t = -1.0f;
    Vec3 n(0.0f);
    // From the axis of the cylinder outward along +x: the wall at distance 1, outward normal +x.
    ASSERT_TRUE(intersect_cone(unit_cylinder(), Vec3(0.0f, 1.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f),
                               0.0f, kInf, t, n));
    EXPECT_NEAR(t, 1.0f, 1e-6f);
    expect_vec_near(n, Vec3(1.0f, 0.0f, 0.0f), 1e-6f);
    // From inside, off the axis at x = −0.5, along +x: the near root (x = −1) is behind the
    // origin, so the hit is the far wall at t = 1.5.
    ASSERT_TRUE(intersect_cone(unit_cylinder(), Vec3(-0.5f, 1.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f),
                               0.0f, kInf, t, n));
    EXPECT_NEAR(t, 1.5f, 1e-6f);
    expect_vec_near(n, Vec3(1.0f, 0.0f, 0.0f), 1e-6f);
    // Inside the pointed cone on its axis at y = 0.5 (radius 0.5): the wall at t = 0.5 along +z.
    const float h = std::sqrt(0.5f);
    ASSERT_TRUE(intersect_cone(pointed_cone(), Vec3(0.0f, 0.5f, 0.0f), Vec3(0.0f, 0.0f, 1.0f), 0.0f,
                               kInf, t, n));
    EXPECT_NEAR(t, 0.5f, 1e-6f);
    expect_vec_near(n, Vec3(0.0f, h, h), 1e-6f);
}

TEST(Cone, DegenerateAxisNeverHits) {
    // Base and apex coincide: no surface.
    Cone c = unit_cylinder();
    c.apex = c.base;
    float t = -1.0f;
    Vec3 n(0.0f);
    EXPECT_FALSE(
        intersect_cone(c, Vec3(-5.0f, 0.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f), 0.0f, kInf, t, n));
}

// The bounds Embree builds the BVH from: every surface point inside, and no looser than needed
// (the extreme points of the sampled surface reach each face of the box within 1%).
TEST(Cone, BoundsAreTightAndContainTheSurface) {
    Cone c;
    c.base = Vec3(1.0f, -2.0f, 0.5f);
    c.apex = Vec3(3.0f, 1.0f, -1.0f);
    c.base_radius = 0.7f;
    c.apex_radius = 0.2f;
    Vec3 lower, upper;
    cone_bounds(c, lower, upper);
    const ConeFrame f = make_cone_frame(c);
    const Vec3 axis(f.axis);
    const Vec3 u = glm::normalize(glm::cross(axis, Vec3(0.0f, 0.0f, 1.0f)));
    const Vec3 v = glm::cross(axis, u);
    Vec3 seen_lower(1e30f), seen_upper(-1e30f);
    for (int i = 0; i <= 100; ++i) {
        const float s = static_cast<float>(i) / 100.0f;
        const Vec3 centre = c.base + s * (c.apex - c.base);
        const float r = c.base_radius + s * (c.apex_radius - c.base_radius);
        for (int k = 0; k < 720; ++k) {
            const float angle = static_cast<float>(k) * kPi / 360.0f;
            const Vec3 p = centre + r * (std::cos(angle) * u + std::sin(angle) * v);
            for (int a = 0; a < 3; ++a) {
                EXPECT_GE(p[a], lower[a] - 1e-6f);
                EXPECT_LE(p[a], upper[a] + 1e-6f);
            }
            seen_lower = glm::min(seen_lower, p);
            seen_upper = glm::max(seen_upper, p);
        }
    }
    for (int a = 0; a < 3; ++a) {
        const float size = upper[a] - lower[a];
        EXPECT_LT(seen_lower[a] - lower[a], 0.01f * size) << a;
        EXPECT_LT(upper[a] - seen_upper[a], 0.01f * size) << a;
    }
}

// The Shape interface of the open cone: crossings of the whole line, entering against the outward
// normal, none along the axis (no caps).
TEST(ConeShape, CrossingsOfTheWholeLine) {
    const Cone c = unit_cylinder();
    ShapeCrossing out[kMaxShapeCrossings];
    ASSERT_EQ(c.crossings(Vec3(-5.0f, 1.0f, 0.0f), Vec3(1, 0, 0), out), 2);
    EXPECT_NEAR(out[0].t, 4.0f, 1e-5f);
    EXPECT_TRUE(out[0].entering);
    EXPECT_NEAR(out[1].t, 6.0f, 1e-5f);
    EXPECT_FALSE(out[1].entering);
    // Above the segment: the infinite cylinder is crossed, the cone is not.
    EXPECT_EQ(c.crossings(Vec3(-5.0f, 3.0f, 0.0f), Vec3(1, 0, 0), out), 0);
    EXPECT_EQ(c.crossings(Vec3(0.0f, -5.0f, 0.0f), Vec3(0, 1, 0), out), 0);
    // From inside, the first crossing is behind the origin.
    ASSERT_EQ(c.crossings(Vec3(0.0f, 1.0f, 0.0f), Vec3(1, 0, 0), out), 2);
    EXPECT_NEAR(out[0].t, -1.0f, 1e-5f);
    EXPECT_NEAR(out[1].t, 1.0f, 1e-5f);
}

}  // namespace
}  // namespace rayo
