// A model file framed with no scene around it (apps/scene/model_scene.h): the camera sees the
// whole bounding sphere, the ground lies under the model, lights face the viewer's side, and
// bad models are refused with the file's name.
#include "apps/scene/model_scene.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/render.h"

namespace rayo {
namespace {

// A box from (1, 2, 3) to (3, 3, 7) as an OBJ (12 triangles).
const char* const kBoxObj = R"(v 1 2 3
v 3 2 3
v 3 3 3
v 1 3 3
v 1 2 7
v 3 2 7
v 3 3 7
v 1 3 7
f 1 3 2
f 1 4 3
f 5 6 7
f 5 7 8
f 1 2 6
f 1 6 5
f 4 7 3
f 4 8 7
f 1 5 8
f 1 8 4
f 2 3 7
f 2 7 6
)";

std::string write_temp(const std::string& name, const std::string& text) {
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("rayo_model_" + std::to_string(::getpid()) + "_" + name))
                                 .string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

TEST(ModelScene, RecognisesModelFilesByExtension) {
    EXPECT_TRUE(is_model_file("a/b.obj"));
    EXPECT_TRUE(is_model_file("B.GLB"));
    EXPECT_TRUE(is_model_file("c.gltf"));
    EXPECT_FALSE(is_model_file("scene.json"));
    EXPECT_FALSE(is_model_file("balls.nff"));
    EXPECT_FALSE(is_model_file("obj"));
}

TEST(ModelScene, CameraSeesTheWholeModelAndTheGroundIsUnderIt) {
    const std::string path = write_temp("box.obj", kBoxObj);
    const SceneDescription d = load_model_scene(path);
    std::filesystem::remove(path);
    ASSERT_EQ(d.scene.meshes.size(), 2u);  // the model and the ground
    EXPECT_EQ(d.scene.meshes[0].triangle_count(), 12u);
    EXPECT_EQ(d.shading.lights.size(), 2u);
    const Vec3 center(2.0f, 2.5f, 5.0f);
    EXPECT_NEAR(glm::length(d.scene.camera.look_at - center), 0.0f, 1e-5f);
    // Every corner of the box projects inside the image, with the margin of the framing.
    const Camera camera = Camera::create(d.scene.camera, "test");
    const Vec3 forward = glm::normalize(d.scene.camera.look_at - d.scene.camera.eye);
    for (const Vec3& p : d.scene.meshes[0].positions) {
        const Vec3 v = p - d.scene.camera.eye;
        EXPECT_GT(glm::dot(v, forward), 0.0f);
        const float angle = glm::degrees(std::acos(glm::dot(glm::normalize(v), forward)));
        EXPECT_LT(angle, 0.5f * camera.vfov_degrees());
    }
    // The ground: every vertex at the box's lowest y, around the box.
    for (const Vec3& p : d.scene.meshes[1].positions) EXPECT_EQ(p.y, 2.0f);
    // The lights come from the viewer's side (their light travels away from the eye).
    const Vec3 to_eye = glm::normalize(d.scene.camera.eye - center);
    for (const Light& light : d.shading.lights) {
        EXPECT_LT(glm::dot(std::get<DirectionalLight>(light).direction, to_eye), 0.0f);
    }
}

TEST(ModelScene, FramingChoicesAreHonoured) {
    const std::string path = write_temp("box_side.obj", kBoxObj);
    ModelFraming framing;
    framing.view_direction = Vec3(-2.0f, 0.0f, 0.0f);
    framing.ground = false;
    const SceneDescription d = load_model_scene(path, framing);
    std::filesystem::remove(path);
    EXPECT_EQ(d.scene.meshes.size(), 1u);
    const Vec3 view = glm::normalize(d.scene.camera.eye - d.scene.camera.look_at);
    EXPECT_NEAR(view.x, -1.0f, 1e-6f);
    // Looking straight down keeps a valid up vector.
    const std::string top = write_temp("box_top.obj", kBoxObj);
    framing.view_direction = Vec3(0.0f, 1.0f, 0.0f);
    const SceneDescription down = load_model_scene(top, framing);
    std::filesystem::remove(top);
    EXPECT_NO_THROW(Camera::create(down.scene.camera, "test"));
}

TEST(ModelScene, BadModelsNameTheFile) {
    const std::string missing = "/nonexistent/model.obj";
    try {
        load_model_scene(missing);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
    const std::string flat = write_temp("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    try {
        load_model_scene(flat);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("flat.obj"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("non-degenerate) triangles"), std::string::npos)
            << e.what();
    }
    std::filesystem::remove(flat);
}

}  // namespace
}  // namespace rayo
