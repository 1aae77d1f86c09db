// SurfaceShading::interact (shading/surface_interaction.h) fills a SurfaceInteraction that the
// path integrator reuses from one vertex of a path to the next: every call must describe its own
// hit, whatever the interaction held before.
#include "shading/surface_interaction.h"

#include <gtest/gtest.h>

#include <string>

#include "apps/scene/json_loader.h"
#include "core/accel.h"

namespace rayo {
namespace {

// Two unit spheres: a textured material (a constant procedural texture as kd) at x = −2, a
// plain one at x = +2.
const char* const kTwoSpheres = R"({"rayo": 1,
  "textures": {"grey": {"type": "constant", "color": [0.2, 0.3, 0.4]}},
  "materials": {"textured": {"kd": "grey"}, "plain": {"kd": [0.9, 0.5, 0.1]}},
  "objects": [
    {"type": "sphere", "center": [-2, 0, 0], "radius": 1, "material": "textured"},
    {"type": "sphere", "center": [2, 0, 0], "radius": 1, "material": "plain"}]})";

Ray ray_down_z(float x) {
    Ray ray;
    ray.origin = Vec3(x, 0.0f, 5.0f);
    ray.direction = Vec3(0.0f, 0.0f, -1.0f);
    return ray;
}

void expect_kd(const SurfaceInteraction& p, const Vec3& kd) {
    EXPECT_NEAR(p.material().kd.x, kd.x, 1e-6f);
    EXPECT_NEAR(p.material().kd.y, kd.y, 1e-6f);
    EXPECT_NEAR(p.material().kd.z, kd.z, 1e-6f);
}

TEST(SurfaceInteraction, AnUntexturedHitAfterATexturedOneShadesWithItsOwnMaterial) {
    const SceneDescription d = load_json_string(kTwoSpheres, "scene.json", "");
    const Accel accel(d.scene, AccelOptions{});
    const SurfaceShading shading(accel, d.shading, nullptr, 0.0f);
    SurfaceInteraction p;  // reused, as the path integrator's vertex is

    const Ray to_textured = ray_down_z(-2.0f);
    SurfaceHit hit;
    ASSERT_TRUE(accel.intersect(to_textured, hit));
    shading.interact(to_textured, hit, p);
    ASSERT_TRUE(p.textured.has_value());
    expect_kd(p, Vec3(0.2f, 0.3f, 0.4f));

    const Ray to_plain = ray_down_z(2.0f);
    ASSERT_TRUE(accel.intersect(to_plain, hit));
    shading.interact(to_plain, hit, p);
    EXPECT_FALSE(p.textured.has_value());
    expect_kd(p, Vec3(0.9f, 0.5f, 0.1f));

    // And back: the textured sphere is textured again.
    ASSERT_TRUE(accel.intersect(to_textured, hit));
    shading.interact(to_textured, hit, p);
    expect_kd(p, Vec3(0.2f, 0.3f, 0.4f));
}

}  // namespace
}  // namespace rayo
