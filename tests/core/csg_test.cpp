// CSG by intervals (core/shapes/csg.h): the boolean merge of crossing lists, hits and flipped
// normals on subtracted surfaces, rays starting inside, nesting, and the pixel coverage of a
// sphere minus a sphere and of a lens (two spheres intersected) through the accel against their
// closed-form projected areas.
#include "core/shapes/csg.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/accel.h"

namespace rayo {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// op(A, B) of two spheres (or any two primitives).
template <typename A, typename B>
Csg csg_of(CsgOp op, const A& a, const B& b) {
    Csg csg;
    const int left = csg.add_leaf(a);
    const int right = csg.add_leaf(b);
    csg.add_operation(op, left, right);
    return csg;
}

TEST(Csg, CombinesIntervalListsByTheBooleanOperation) {
    // A = [0, 4], B = [2, 6] ∪ [7, 8].
    const Vec3 na(1, 0, 0), nb(0, 1, 0);
    const ShapeCrossing a[] = {{0.0f, true, -na}, {4.0f, false, na}};
    const ShapeCrossing b[] = {
        {2.0f, true, -nb}, {6.0f, false, nb}, {7.0f, true, -nb}, {8.0f, false, nb}};
    ShapeCrossing out[6];
    ASSERT_EQ(combine_crossings(CsgOp::Union, a, 2, b, 4, out), 4);
    EXPECT_EQ(out[0].t, 0.0f);
    EXPECT_EQ(out[1].t, 6.0f);
    EXPECT_EQ(out[2].t, 7.0f);
    EXPECT_EQ(out[3].t, 8.0f);
    ASSERT_EQ(combine_crossings(CsgOp::Intersection, a, 2, b, 4, out), 2);
    EXPECT_EQ(out[0].t, 2.0f);
    EXPECT_TRUE(out[0].entering);
    EXPECT_EQ(out[0].normal, -nb);
    EXPECT_EQ(out[1].t, 4.0f);
    EXPECT_FALSE(out[1].entering);
    EXPECT_EQ(out[1].normal, na);
    // A∖B = [0, 2]: the result leaves where B enters, and B's normal flips there.
    ASSERT_EQ(combine_crossings(CsgOp::Difference, a, 2, b, 4, out), 2);
    EXPECT_EQ(out[0].t, 0.0f);
    EXPECT_EQ(out[1].t, 2.0f);
    EXPECT_FALSE(out[1].entering);
    EXPECT_EQ(out[1].normal, nb);
    // B∖A = [4, 6] ∪ [7, 8]: entering where A leaves, A's normal flipped.
    ASSERT_EQ(combine_crossings(CsgOp::Difference, b, 4, a, 2, out), 4);
    EXPECT_EQ(out[0].t, 4.0f);
    EXPECT_TRUE(out[0].entering);
    EXPECT_EQ(out[0].normal, -na);
}

TEST(Csg, SphereMinusSphereHitsTheCarvedSurfaceWithAFlippedNormal) {
    // A unit sphere at the origin minus a sphere of radius 0.5 at (0, 0, 1): a ray down the
    // z axis from +z enters the bite at z = 0.5 (B's surface, normal +z there: into B's hole).
    const Csg csg = csg_of(CsgOp::Difference, Sphere{Vec3(0.0f), 1.0f, 0},
                           Sphere{Vec3(0.0f, 0.0f, 1.0f), 0.5f, 0});
    ShapeHit hit;
    ASSERT_TRUE(csg.nearest(Vec3(0, 0, 5), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 4.5f, 1e-5f);
    EXPECT_GT(glm::normalize(hit.normal).z, 0.999f);  // faces the ray, out of the solid
    // Beside the bite the sphere's own front: x = 0.8, z = 0.6 (outside B: |(0.8, 0, −0.4)| >
    // 0.5).
    ASSERT_TRUE(csg.nearest(Vec3(0.8f, 0, 5), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 4.4f, 1e-5f);
    EXPECT_NEAR(glm::normalize(hit.normal).x, 0.8f, 1e-5f);
    // Through the bite's rim from the side: misses where only B is.
    EXPECT_FALSE(csg.nearest(Vec3(5, 0, 1.2f), Vec3(-1, 0, 0), 0.0f, kInf, hit));
}

TEST(Csg, RaysStartingInsideLeaveThroughTheRightSurface) {
    const Csg csg = csg_of(CsgOp::Difference, Sphere{Vec3(0.0f), 1.0f, 0},
                           Sphere{Vec3(0.0f, 0.0f, 1.0f), 0.5f, 0});
    ShapeHit hit;
    // From the centre toward +z: leaves A∖B where B begins (z = 0.5); the outward normal
    // there is B's (−z) flipped: +z, out of the solid into the bite.
    ASSERT_TRUE(csg.nearest(Vec3(0.0f), Vec3(0, 0, 1), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 0.5f, 1e-5f);
    EXPECT_GT(glm::normalize(hit.normal).z, 0.999f);
    // From the centre toward −z: leaves through A at z = −1, normal −z.
    ASSERT_TRUE(csg.nearest(Vec3(0.0f), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 1.0f, 1e-5f);
    EXPECT_LT(glm::normalize(hit.normal).z, -0.999f);
    // From inside the bite (outside the solid) toward −z: enters A∖B at z = 0.5.
    ASSERT_TRUE(csg.nearest(Vec3(0, 0, 0.9f), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 0.4f, 1e-5f);
    EXPECT_GT(glm::normalize(hit.normal).z, 0.999f);
}

TEST(Csg, NestsThreeDeep) {
    // ((box ∩ sphere) ∖ cylinder) ∪ sphere: the rounded cube with a hole along z, and a small
    // ball in the hole.
    Csg csg;
    Box box;
    box.min = Vec3(-1.0f);
    box.max = Vec3(1.0f);
    const int cube = csg.add_leaf(box);
    const int ball = csg.add_leaf(Sphere{Vec3(0.0f), 1.3f, 0});
    const int rounded = csg.add_operation(CsgOp::Intersection, cube, ball);
    Cylinder drill;
    drill.base = Vec3(0, 0, -2);
    drill.top = Vec3(0, 0, 2);
    drill.radius = 0.5f;
    const int hole = csg.add_leaf(drill);
    const int drilled = csg.add_operation(CsgOp::Difference, rounded, hole);
    const int pearl = csg.add_leaf(Sphere{Vec3(0.0f), 0.25f, 0});
    csg.add_operation(CsgOp::Union, drilled, pearl);
    ShapeHit hit;
    // Down the axis: through the hole onto the pearl.
    ASSERT_TRUE(csg.nearest(Vec3(0, 0, 5), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 4.75f, 1e-5f);
    // Beside the pearl, in the hole: through and out the far side.
    EXPECT_FALSE(csg.nearest(Vec3(0.4f, 0, 5), Vec3(0, 0, -1), 0.0f, kInf, hit));
    // Off the hole: the cube's face z = 1 (inside the rounding sphere there).
    ASSERT_TRUE(csg.nearest(Vec3(0.7f, 0, 5), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 4.0f, 1e-5f);
    EXPECT_EQ(hit.normal, Vec3(0, 0, 1));
    // The cube's corner region is cut by the sphere: at (0.8, 0.8) the face z = 1 is outside
    // the sphere (0.8² + 0.8² + 1 > 1.3²), the sphere's surface is hit below it.
    ASSERT_TRUE(csg.nearest(Vec3(0.8f, 0.8f, 5), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 5.0f - std::sqrt(1.69f - 1.28f), 1e-4f);
    EXPECT_NEAR(glm::normalize(hit.normal).x, 0.8f / 1.3f, 1e-4f);
    // From inside the hole's wall (in the solid) sideways: out into the hole at x = 0.5.
    ASSERT_TRUE(csg.nearest(Vec3(0.8f, 0, 0.5f), Vec3(-1, 0, 0), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 0.3f, 1e-5f);
    // Out of the solid into the hole: −x, the drill's outward +x there flipped.
    EXPECT_LT(glm::normalize(hit.normal).x, -0.999f);
    EXPECT_EQ(csg.leaf_budget(), 4 * kMaxShapeCrossings);
}

// The fraction of a grid of parallel rays (down −z over [−s, s]², an orthographic view) that
// hit the CSG through the accel, times the grid's area: the projected area.
double projected_area(const Csg& csg, double half_side, int n) {
    Scene scene;
    scene.shapes.of<Csg>().push_back(csg);
    const Accel accel(scene, AccelOptions{});
    int hits = 0;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            Ray ray;
            ray.origin = Vec3(static_cast<float>(half_side * (2.0 * (i + 0.5) / n - 1.0)),
                              static_cast<float>(half_side * (2.0 * (j + 0.5) / n - 1.0)), 10.0f);
            ray.direction = Vec3(0, 0, -1);
            SurfaceHit hit;
            if (accel.intersect(ray, hit)) {
                ++hits;
                EXPECT_EQ(hit.shape, Shapes::index_of<Csg>());
            }
        }
    }
    return hits * (2.0 * half_side) * (2.0 * half_side) / (double(n) * n);
}

TEST(Csg, SphereMinusSphereCoversItsClosedFormProjectedArea) {
    // Unit spheres at the origin and at (d, 0, 0): along z a line through A's disc keeps part
    // of A's chord exactly when x < d/2 (B's chord is then the shorter). The projected area is
    // A's disc less the segment beyond x = h = d/2: π − (acos h − h·√(1 − h²)).
    const double d = 0.8, h = d / 2;
    const Csg csg = csg_of(CsgOp::Difference, Sphere{Vec3(0.0f), 1.0f, 0},
                           Sphere{Vec3(float(d), 0.0f, 0.0f), 1.0f, 0});
    const double expected = M_PI - (std::acos(h) - h * std::sqrt(1.0 - h * h));
    EXPECT_NEAR(projected_area(csg, 1.1, 500), expected, 2e-3 * expected);
}

TEST(Csg, LensCoversItsClosedFormProjectedArea) {
    // Unit spheres at (±d/2, 0, 0) intersected: along z their chords are centred on z = 0, so
    // they overlap exactly where both discs do. Two unit discs at distance d overlap in
    // 2·acos(d/2) − (d/2)·√(4 − d²).
    const double d = 1.2;
    const Csg csg = csg_of(CsgOp::Intersection, Sphere{Vec3(float(-d / 2), 0.0f, 0.0f), 1.0f, 0},
                           Sphere{Vec3(float(d / 2), 0.0f, 0.0f), 1.0f, 0});
    const double expected = 2.0 * std::acos(d / 2) - (d / 2) * std::sqrt(4.0 - d * d);
    EXPECT_NEAR(projected_area(csg, 1.1, 500), expected, 2e-3 * expected);
    // And its union: both discs less the overlap once.
    const Csg both = csg_of(CsgOp::Union, Sphere{Vec3(float(-d / 2), 0.0f, 0.0f), 1.0f, 0},
                            Sphere{Vec3(float(d / 2), 0.0f, 0.0f), 1.0f, 0});
    EXPECT_NEAR(projected_area(both, 1.7, 500), 2.0 * M_PI - expected, 2e-3 * expected);
}

TEST(Csg, BoundsFollowTheOperation) {
    const Sphere a{Vec3(0.0f), 1.0f, 0}, b{Vec3(1.5f, 0.0f, 0.0f), 1.0f, 0};
    EXPECT_EQ(csg_of(CsgOp::Union, a, b).bounds().upper.x, 2.5f);
    EXPECT_EQ(csg_of(CsgOp::Intersection, a, b).bounds().lower.x, 0.5f);
    EXPECT_EQ(csg_of(CsgOp::Intersection, a, b).bounds().upper.x, 1.0f);
    EXPECT_EQ(csg_of(CsgOp::Difference, a, b).bounds().upper.x, 1.0f);
}

}  // namespace
}  // namespace rayo
