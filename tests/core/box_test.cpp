// The axis-aligned box shape (core/shapes/box.h): slab hits and face normals from outside and
// inside, crossings, misses, the min < max rule, and the box through the accel.
#include "core/shapes/box.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/accel.h"

namespace rayo {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

Box unit_box() {
    Box b;
    b.min = Vec3(-1.0f, 0.0f, 2.0f);
    b.max = Vec3(1.0f, 3.0f, 4.0f);
    return b;
}

TEST(Box, HitsTheNearFaceWithItsOutwardNormal) {
    const Box b = unit_box();
    ShapeHit hit;
    ASSERT_TRUE(b.nearest(Vec3(0.5f, 1.0f, -6.0f), Vec3(0, 0, 1), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 8.0f);
    EXPECT_EQ(hit.normal, Vec3(0, 0, -1));
    ASSERT_TRUE(b.nearest(Vec3(5.0f, 1.0f, 3.0f), Vec3(-1, 0, 0), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 4.0f);
    EXPECT_EQ(hit.normal, Vec3(1, 0, 0));
    ASSERT_TRUE(b.nearest(Vec3(0.0f, 10.0f, 3.0f), Vec3(0, -1, 0), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 7.0f);
    EXPECT_EQ(hit.normal, Vec3(0, 1, 0));
}

TEST(Box, FromInsideHitsTheExitFace) {
    const Box b = unit_box();
    ShapeHit hit;
    ASSERT_TRUE(b.nearest(Vec3(0.0f, 1.0f, 3.0f), Vec3(0, 0, 1), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 1.0f);
    EXPECT_EQ(hit.normal, Vec3(0, 0, 1));
    Ray ray;
    ray.origin = Vec3(0.0f, 1.0f, 3.0f);
    ray.direction = Vec3(0, 0, 1);
    SurfaceHit surface;
    b.surface(ray, hit, surface);
    EXPECT_EQ(surface.position.z, 4.0f);
    EXPECT_EQ(surface.object_size, 3.0f);
}

TEST(Box, TwoCrossingsSortedEnteringThenLeaving) {
    const Box b = unit_box();
    ShapeCrossing c[kMaxShapeCrossings];
    const Vec3 d = glm::normalize(Vec3(1.0f, 1.0f, 1.0f));
    ASSERT_EQ(b.crossings(Vec3(-1.5f, -0.5f, 1.5f), d, c), 2);
    EXPECT_LT(c[0].t, c[1].t);
    EXPECT_TRUE(c[0].entering);
    EXPECT_FALSE(c[1].entering);
    EXPECT_NEAR(c[0].t, 0.5f * std::sqrt(3.0f), 1e-5f);  // enters at x = −1, y = 0, z = 2
    EXPECT_NEAR(c[1].t, 2.5f * std::sqrt(3.0f), 1e-5f);  // leaves through z = 4
}

TEST(Box, MissesBesideAndBehind) {
    const Box b = unit_box();
    ShapeHit hit;
    EXPECT_FALSE(b.nearest(Vec3(1.01f, 1.0f, -6.0f), Vec3(0, 0, 1), 0.0f, kInf, hit));
    EXPECT_FALSE(b.nearest(Vec3(0.0f, 1.0f, -6.0f), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_FALSE(b.nearest(Vec3(0.0f, 1.0f, -6.0f), Vec3(0, 0, 1), 0.0f, 7.9f, hit));
}

TEST(Box, MinMustBeBelowMaxOnEveryAxis) {
    EXPECT_FALSE(unit_box().problem());
    Box b = unit_box();
    b.max.y = b.min.y;
    ASSERT_TRUE(b.problem());
    EXPECT_EQ(b.problem()->field, "max");
}

TEST(Box, ThroughTheAccelAsUserGeometry) {
    Scene scene;
    scene.shapes.of<Box>().push_back(unit_box());
    scene.shapes.of<Sphere>().push_back({Vec3(0.0f, 1.0f, 10.0f), 1.0f, 1});
    AccelOptions options;
    const Accel accel(scene, options);
    Ray ray;
    ray.origin = Vec3(0.0f, 1.0f, 20.0f);
    ray.direction = Vec3(0, 0, -1);
    SurfaceHit hit;
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_EQ(hit.shape, Shapes::index_of<Sphere>());
    ray.origin.z = 8.0f;
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_EQ(hit.shape, Shapes::index_of<Box>());
    EXPECT_FLOAT_EQ(hit.t, 4.0f);
    EXPECT_EQ(hit.geometric_normal, Vec3(0, 0, 1));
}

}  // namespace
}  // namespace rayo
