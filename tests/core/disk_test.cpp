// The disk shape (core/shapes/disk.h): analytic hits and normals, the rim, parallel rays,
// crossings, bounds, and the disk through the accel as Embree user geometry.
#include "core/shapes/disk.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/accel.h"

namespace rayo {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

Disk unit_disk_facing_z() {
    Disk d;
    d.center = Vec3(1.0f, 2.0f, 3.0f);
    d.normal = Vec3(0.0f, 0.0f, 1.0f);
    d.radius = 2.0f;
    return d;
}

TEST(Disk, HitsThePlaneInsideTheRadiusAtTheAnalyticDistance) {
    const Disk d = unit_disk_facing_z();
    ShapeHit hit;
    // From z = 10 straight down, 1.5 from the centre: t = 7.
    ASSERT_TRUE(d.nearest(Vec3(2.5f, 2.0f, 10.0f), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 7.0f);
    // Slanted: from (1, 2, 3) + (3, 0, 4) towards the centre, distance 5.
    ASSERT_TRUE(d.nearest(Vec3(4.0f, 2.0f, 7.0f), Vec3(-0.6f, 0.0f, -0.8f), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 5.0f, 1e-5f);
    Ray ray;
    ray.origin = Vec3(4.0f, 2.0f, 7.0f);
    ray.direction = Vec3(-0.6f, 0.0f, -0.8f);
    SurfaceHit surface;
    d.surface(ray, hit, surface);
    EXPECT_NEAR(surface.position.x, 1.0f, 1e-5f);
    EXPECT_EQ(surface.position.z, 3.0f);  // projected onto the plane
    EXPECT_EQ(surface.geometric_normal, d.normal);
}

TEST(Disk, MissesOutsideTheRimParallelAndOutsideTheWindow) {
    const Disk d = unit_disk_facing_z();
    ShapeHit hit;
    EXPECT_FALSE(d.nearest(Vec3(3.01f, 2.0f, 10.0f), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_TRUE(d.nearest(Vec3(2.99f, 2.0f, 10.0f), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_FALSE(d.nearest(Vec3(1.0f, 2.0f, 3.0f), Vec3(1, 0, 0), -kInf, kInf, hit));
    EXPECT_FALSE(d.nearest(Vec3(1.0f, 2.0f, 10.0f), Vec3(0, 0, -1), 0.0f, 6.9f, hit));
    EXPECT_FALSE(d.nearest(Vec3(1.0f, 2.0f, 10.0f), Vec3(0, 0, 1), 0.0f, kInf, hit));
}

TEST(Disk, OneCrossingEnteringAgainstTheNormal) {
    const Disk d = unit_disk_facing_z();
    ShapeCrossing c[kMaxShapeCrossings];
    ASSERT_EQ(d.crossings(Vec3(1, 2, 10), Vec3(0, 0, -1), c), 1);
    EXPECT_FLOAT_EQ(c[0].t, 7.0f);
    EXPECT_TRUE(c[0].entering);
    ASSERT_EQ(d.crossings(Vec3(1, 2, -10), Vec3(0, 0, 1), c), 1);
    EXPECT_FLOAT_EQ(c[0].t, 13.0f);
    EXPECT_FALSE(c[0].entering);
}

TEST(Disk, BoundsHoldTheRim) {
    Disk d = unit_disk_facing_z();
    d.normal = glm::normalize(Vec3(1.0f, 1.0f, 0.5f));
    const Bounds3 b = d.bounds();
    const Vec3 helper = glm::normalize(glm::cross(d.normal, Vec3(0, 0, 1)));
    const Vec3 other = glm::cross(d.normal, helper);
    for (int i = 0; i < 64; ++i) {
        const float a = 2.0f * kPi * static_cast<float>(i) / 64.0f;
        const Vec3 p = d.center + d.radius * (std::cos(a) * helper + std::sin(a) * other);
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GE(p[axis], b.lower[axis]);
            EXPECT_LE(p[axis], b.upper[axis]);
        }
    }
    // Tight: a disk facing z spans exactly its radius in x and y and nothing in z.
    const Bounds3 flat = unit_disk_facing_z().bounds();
    EXPECT_NEAR(flat.upper.x - flat.lower.x, 4.0f, 1e-3f);
    EXPECT_NEAR(flat.upper.z - flat.lower.z, 0.0f, 1e-6f);
}

TEST(Disk, ThroughTheAccelAsUserGeometry) {
    Scene scene;
    Disk d = unit_disk_facing_z();
    d.material = 3;
    scene.shapes.of<Disk>().push_back(d);
    const Accel accel(scene);
    Ray ray;
    ray.origin = Vec3(2.0f, 2.5f, 10.0f);
    ray.direction = Vec3(0, 0, -1);
    SurfaceHit hit;
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_FLOAT_EQ(hit.t, 7.0f);
    EXPECT_EQ(hit.shape, Shapes::index_of<Disk>());
    EXPECT_EQ(hit.material, 3u);
    EXPECT_TRUE(accel.occluded(ray));
    accel.parameterize(hit);
    EXPECT_NEAR(hit.uv.y, std::sqrt(1.25f) / 2.0f, 1e-5f);  // ρ/r
    ray.origin.x = 4.0f;
    EXPECT_FALSE(accel.intersect(ray, hit));
}

}  // namespace
}  // namespace rayo
