// `auto`'s choice of sphere method and precision, and the icosphere level for an error budget.
#include <gtest/gtest.h>

#include "apps/scene/sphere_method_choice.h"
#include "core/shapes/icosphere.h"

namespace rayo {
namespace {

SceneDescription one_sphere_scene(const Vec3& offset, float radius, float distance) {
    SceneDescription d;
    d.scene.camera.eye = offset + Vec3(0, 0, distance);
    d.scene.camera.look_at = offset;
    d.scene.camera.vfov_degrees = 45.0f;
    d.scene.camera.width = d.scene.camera.height = 512;
    d.scene.shapes.of<Sphere>().push_back({offset, radius, 0});
    d.shading.materials.emplace_back();
    return d;
}

TEST(SphereMethodChoice, AutoPicksAnalyticStableNearTheOrigin) {
    const SceneDescription d = one_sphere_scene(Vec3(0), 1.0f, 5.0f);
    const SphereChoice c = choose_sphere_method(d, Camera::create(d.scene.camera));
    EXPECT_EQ(c.spheres.method, SphereMethod::User);
    EXPECT_EQ(c.math, SphereMath::Stable);
    EXPECT_NE(c.reason.find("mesh would need level"), std::string::npos) << c.reason;
}

TEST(SphereMethodChoice, TinySpheresFarFromTheOriginAreReportedNotDoubled) {
    // A 1 mm sphere seen from 1 cm, 1e5 units from the origin: float ulps there are ~0.008, so
    // the silhouette is off by pixels for every method; double cannot help (docs/stability.md).
    const SceneDescription d = one_sphere_scene(Vec3(1e5f, 0, 0), 1e-3f, 1e-2f);
    const SphereChoice c = choose_sphere_method(d, Camera::create(d.scene.camera));
    EXPECT_EQ(c.spheres.method, SphereMethod::User);
    EXPECT_EQ(c.math, SphereMath::Stable);
    EXPECT_NE(c.reason.find("beyond float's resolution"), std::string::npos) << c.reason;
}

TEST(SphereMethodChoice, ExplicitChoicesAreKept) {
    SceneDescription d = one_sphere_scene(Vec3(0), 1.0f, 5.0f);
    d.settings.spheres = *parse_sphere_method("mesh:2");
    SphereChoice c = choose_sphere_method(d, Camera::create(d.scene.camera));
    EXPECT_EQ(c.spheres.method, SphereMethod::Mesh);
    EXPECT_EQ(c.reason, "as requested");
    d.settings.spheres = *parse_sphere_method("auto");
    d.settings.sphere_math = SphereMath::Seed;
    c = choose_sphere_method(d, Camera::create(d.scene.camera));
    EXPECT_EQ(c.math, SphereMath::Seed);
}

TEST(SphereMethodChoice, IcosphereLevelGrowsWithProjectedSize) {
    EXPECT_EQ(icosphere_level_for(1.0f, 0.5f), 0);
    int previous = 0;
    for (float radius_px : {4.0f, 16.0f, 64.0f, 256.0f, 1024.0f}) {
        const int level = icosphere_level_for(radius_px, 0.5f);
        EXPECT_GE(level, previous);
        EXPECT_LE(radius_px * kIcosphereMaxDepth[level], 0.5f);
        if (level > 0) EXPECT_GT(radius_px * kIcosphereMaxDepth[level - 1], 0.5f);
        previous = level;
    }
    EXPECT_GT(previous, 2);
}
}  // namespace
}  // namespace rayo
