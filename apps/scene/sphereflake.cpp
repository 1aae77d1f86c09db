#include "apps/scene/sphereflake.h"

#include <cmath>

#include "core/error.h"

namespace rayo {
namespace {

// Child directions in the parent's frame: six around the equator (tilted slightly down) and
// three on the upper cap, so children do not overlap.
void add_children(std::vector<Sphere>& spheres, const Vec3& center, float radius, const Vec3& axis,
                  int depth, uint32_t material) {
    if (depth == 0) return;
    const Vec3 helper = std::abs(axis.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = glm::normalize(glm::cross(axis, helper));
    const Vec3 v = glm::cross(axis, u);
    const float child_radius = radius / 3.0f;
    auto place = [&](float azimuth, float elevation) {
        const Vec3 direction =
            std::cos(elevation) * (std::cos(azimuth) * u + std::sin(azimuth) * v) +
            std::sin(elevation) * axis;
        const Vec3 child_center = center + (radius + child_radius) * direction;
        spheres.push_back({child_center, child_radius, material});
        add_children(spheres, child_center, child_radius, direction, depth - 1, material);
    };
    for (int i = 0; i < 6; ++i) place(static_cast<float>(i) * kPi / 3.0f, -0.2f);
    for (int i = 0; i < 3; ++i) place(kPi / 6.0f + static_cast<float>(i) * 2.0f * kPi / 3.0f, 0.9f);
}

}  // namespace

void add_sphereflake(std::vector<Sphere>& spheres, const Vec3& center, float radius,
                     const Vec3& axis, int depth, uint32_t material) {
    spheres.push_back({center, radius, material});
    add_children(spheres, center, radius, axis, depth, material);
}

SceneDescription make_sphereflake(int depth, int width, int height) {
    if (depth < 0 || depth > kMaxSphereflakeDepth)
        throw InputError("sphereflake", "depth must be in [0, 6]");
    SceneDescription d;
    d.source = "<sphereflake " + std::to_string(depth) + ">";
    d.scene.camera.eye = Vec3(2.1f, 1.3f, 1.7f);
    d.scene.camera.look_at = Vec3(0.0f);
    d.scene.camera.up = Vec3(0, 0, 1);
    d.scene.camera.vfov_degrees = 45.0f;
    d.scene.camera.fov_spans_pixel_centres = true;
    d.scene.camera.width = width;
    d.scene.camera.height = height;
    d.shading.background = Vec3(0.078f, 0.361f, 0.753f);

    Material floor;  // SPD balls: f 1 0.75 0.33 0.8 0 100000 0 1
    floor.kd = 0.8f * Vec3(1.0f, 0.75f, 0.33f);
    floor.ka = 0.1f * Vec3(1.0f, 0.75f, 0.33f);
    d.shading.materials.push_back(floor);
    Material ball;  // SPD balls: f 1 0.9 0.7 0.5 0.5 3.0827 0 1
    ball.kd = 0.5f * Vec3(1.0f, 0.9f, 0.7f);
    ball.ka = 0.1f * Vec3(1.0f, 0.9f, 0.7f);
    ball.ks = Vec3(0.5f);
    ball.shininess = 3.0827f;
    ball.reflect = Vec3(0.5f);
    d.shading.materials.push_back(ball);

    TriangleMesh ground;
    ground.name = "floor";
    ground.one_sided = true;
    ground.add_convex_polygon(
        {Vec3(12, 12, -0.5f), Vec3(-12, 12, -0.5f), Vec3(-12, -12, -0.5f), Vec3(12, -12, -0.5f)},
        {}, 0);
    d.scene.meshes.push_back(std::move(ground));
    add_sphereflake(d.scene.shapes.of<Sphere>(), Vec3(0.0f), 0.5f, Vec3(0, 0, 1), depth, 1);

    for (const Vec3& p : {Vec3(4, 3, 2), Vec3(1, -4, 4), Vec3(-3, 1, 5)}) {
        PointLight light;
        light.position = p;
        d.shading.lights.push_back(light);
    }
    return d;
}

}  // namespace rayo
