// Tests of the area lights (shading/area_light.h) through the light interface (light.h): the
// irradiance their stratified samples estimate against the closed forms for a disk, a
// rectangle and a sphere, the points lying on the emitting surface, the one-sided emitters.
#include "shading/area_light.h"

#include <gtest/gtest.h>

#include <cmath>

#include "shading/light.h"

namespace rayo {
namespace {

// The irradiance at `point` on a surface of normal `normal` from `count` samples of `light`
// (light index 0), as the Whitted integrator sums it: Σ L·cos θ/pdf / count, no occlusion.
double irradiance(const Light& light, const Vec3& point, const Vec3& normal) {
    const int count = light_sample_count(light);
    double sum = 0.0;
    for (int s = 0; s < count; ++s) {
        LightSample sample;
        if (!sample_light(light, point, light_sample_u(point, 0, s, count), sample)) continue;
        const float cosine = glm::dot(normal, sample.direction);
        if (cosine > 0.0f) sum += sample.radiance.x * cosine / sample.pdf;
    }
    return sum / count;
}

AreaLight disk_light(float radius, float height, int samples) {
    AreaLight light;
    light.shape = AreaLight::Shape::Disk;
    light.center = Vec3(0.0f, height, 0.0f);
    light.normal = Vec3(0.0f, -1.0f, 0.0f);
    light.radius = radius;
    light.color = Vec3(1.0f);
    light.intensity = 3.0f;  // L = 3
    light.samples = samples;
    return light;
}

TEST(AreaLight, DiskIrradianceOnItsAxisMatchesTheClosedForm) {
    // E = π·L·R²/(h² + R²) on the axis of a disk of radiance L, radius R, at height h.
    for (float h : {0.5f, 2.0f, 10.0f}) {
        const AreaLight light = disk_light(1.0f, h, 256);
        const double expected = kPi * 3.0 * 1.0 / (h * h + 1.0);
        EXPECT_NEAR(irradiance(light, Vec3(0.0f), Vec3(0, 1, 0)), expected, 0.01 * expected)
            << "h " << h;
    }
}

TEST(AreaLight, RectangleIrradianceBelowACornerMatchesTheFormFactor) {
    // A point at height h below a corner of a parallel a×b rectangle: E = π·L·F with
    // F = 1/(2π)·[A/√(1+A²)·atan(B/√(1+A²)) + B/√(1+B²)·atan(A/√(1+B²))], A = a/h, B = b/h.
    AreaLight light;
    light.shape = AreaLight::Shape::Rectangle;
    light.corner = Vec3(0.0f, 2.0f, 0.0f);
    light.edge1 = Vec3(1.5f, 0.0f, 0.0f);  // edge1 × edge2 = −y: emits down
    light.edge2 = Vec3(0.0f, 0.0f, 3.0f);
    light.intensity = 2.0f;
    light.samples = 400;
    const double a = 3.0 / 2.0, b = 1.5 / 2.0;
    const double f = (a / std::sqrt(1 + a * a) * std::atan(b / std::sqrt(1 + a * a)) +
                      b / std::sqrt(1 + b * b) * std::atan(a / std::sqrt(1 + b * b))) /
                     (2.0 * kPi);
    const double expected = kPi * 2.0 * f;
    EXPECT_NEAR(irradiance(light, Vec3(0.0f), Vec3(0, 1, 0)), expected, 0.01 * expected);
    // Seen from above, the rectangle shows its back: no light.
    LightSample sample;
    EXPECT_FALSE(sample_light(light, Vec3(0.5f, 5.0f, 0.5f), glm::vec2(0.5f), sample));
}

TEST(AreaLight, SphereIrradianceFacingItIsPiLTimesSinSquared) {
    // A sphere of radiance L, radius r, centre at distance d along the normal: E = π·L·(r/d)².
    AreaLight light;
    light.shape = AreaLight::Shape::Sphere;
    light.center = Vec3(0.0f, 4.0f, 0.0f);
    light.radius = 1.5f;
    light.samples = 256;
    const double expected = kPi * (1.5 / 4.0) * (1.5 / 4.0);
    EXPECT_NEAR(irradiance(light, Vec3(0.0f), Vec3(0, 1, 0)), expected, 0.01 * expected);
    LightSample sample;
    EXPECT_FALSE(sample_light(light, Vec3(0.0f, 4.5f, 0.0f), glm::vec2(0.5f), sample));  // inside
}

TEST(AreaLight, SamplesLieOnTheEmittingSurface) {
    const Vec3 point(0.3f, -0.2f, 0.1f);
    AreaLight sphere;
    sphere.shape = AreaLight::Shape::Sphere;
    sphere.center = Vec3(1.0f, 3.0f, -2.0f);
    sphere.radius = 0.7f;
    const AreaLight disk = disk_light(0.8f, 2.5f, 16);
    for (int s = 0; s < 16; ++s) {
        const glm::vec2 u = light_sample_u(point, 0, s, 16);
        LightSample sample;
        ASSERT_TRUE(sphere.sample(point, u, sample));
        const Vec3 on_sphere = point + sample.distance * sample.direction;
        EXPECT_NEAR(glm::length(on_sphere - sphere.center), sphere.radius, 1e-5f);
        // The visible side: the surface faces back toward the point.
        EXPECT_LT(glm::dot(on_sphere - sphere.center, sample.direction), 0.0f);
        ASSERT_TRUE(disk.sample(point, u, sample));
        const Vec3 on_disk = point + sample.distance * sample.direction;
        EXPECT_NEAR(on_disk.y, 2.5f, 1e-5f);
        EXPECT_LE(glm::length(on_disk - disk.center), 0.8f + 1e-5f);
    }
}

TEST(AreaLight, SampleSetsAreStratifiedAndDependOnlyOnThePoint) {
    // 16 samples: one per cell of a 4×4 grid, the same set for the same point and light.
    const Vec3 point(1.0f, 2.0f, 3.0f);
    int cells[16] = {};
    for (int s = 0; s < 16; ++s) {
        const glm::vec2 u = light_sample_u(point, 2, s, 16);
        ASSERT_GE(u.x, 0.0f);
        ASSERT_LT(u.x, 1.0f);
        ASSERT_GE(u.y, 0.0f);
        ASSERT_LT(u.y, 1.0f);
        ++cells[static_cast<int>(u.x * 4) + 4 * static_cast<int>(u.y * 4)];
        EXPECT_EQ(u, light_sample_u(point, 2, s, 16));
    }
    for (int c : cells) EXPECT_EQ(c, 1);
    EXPECT_NE(light_sample_u(point, 2, 0, 16), light_sample_u(point, 3, 0, 16));
    EXPECT_NE(light_sample_u(point, 2, 0, 16), light_sample_u(Vec3(1.0f, 2.0f, 3.5f), 2, 0, 16));
    EXPECT_EQ(light_sample_u(point, 2, 0, 1), glm::vec2(0.5f));
}

}  // namespace
}  // namespace rayo
