// Vertex colours (TriangleMesh::colors) multiply the material's kd and ka where the shader sees
// them: a red-vertexed triangle keeps the red channel of the uncoloured one and loses the others.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "apps/scene/json_loader.h"
#include "core/accel.h"
#include "shading/integrators/whitted.h"

namespace rayo {
namespace {

Vec3 radiance_of_triangle(const std::string& obj_vertices) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("rayo_vertex_color_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "t.obj") << obj_vertices << "f 1 2 3\n";
    const SceneDescription d = load_json_string(
        R"({"rayo": 1, "ambient_light": 1,
            "materials": {"default": {"ka": 0.2, "kd": [0.6, 0.7, 0.8], "ks": 0}},
            "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1}],
            "objects": [{"type": "mesh", "file": "t.obj"}]})",
        "scene.json", dir.string());
    std::filesystem::remove_all(dir);
    const Accel accel(d.scene, AccelOptions{});
    const WhittedIntegrator integrator(accel, d.shading, d.settings.whitted());
    Ray ray;
    ray.origin = Vec3(0.25f, 0.25f, 5.0f);
    ray.direction = Vec3(0.0f, 0.0f, -1.0f);
    RayCounters counters;
    return integrator.radiance(ray, counters);
}

TEST(VertexColor, MultipliesDiffuseAndAmbient) {
    const Vec3 plain = radiance_of_triangle("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    const Vec3 red = radiance_of_triangle("v 0 0 0 1 0 0\nv 1 0 0 1 0 0\nv 0 1 0 1 0 0\n");
    EXPECT_NEAR(plain.x, 0.2f + 0.6f, 1e-5f);  // ka·Ia + kd·Il·cos 0
    EXPECT_FLOAT_EQ(red.x, plain.x);
    EXPECT_EQ(red.y, 0.0f);
    EXPECT_EQ(red.z, 0.0f);
    // Interpolated: at (0.25, 0.25) the white third corner weighs 0.25, so green is a quarter
    // of the uncoloured triangle's.
    const Vec3 blend = radiance_of_triangle("v 0 0 0 1 0 0\nv 1 0 0 1 0 0\nv 0 1 0 1 1 1\n");
    EXPECT_NEAR(blend.y, 0.25f * plain.y, 1e-5f);
}

}  // namespace
}  // namespace rayo
