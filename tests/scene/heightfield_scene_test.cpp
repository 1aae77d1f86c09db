// Height fields in JSON scenes (docs/heightfields.md): images read at their bit depth (a 16-bit
// PNG keeps its 16 bits, RGB as luminance), procedural fields from a named texture, the `dda`
// and `mesh` methods rendering the same picture, `auto`'s choice, and bad values refused at
// their JSON pointer.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <vector>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/error.h"

namespace rayo {
namespace {

std::string temp_path(const std::string& name) {
    return ::testing::TempDir() + name;
}

// Writes a width × height image of `channels` channels of `type` from float values.
void write_image(const std::string& path, int width, int height, int channels, OIIO::TypeDesc type,
                 const std::vector<float>& values) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    const OIIO::ImageSpec spec(width, height, channels, type);
    ASSERT_TRUE(out->open(path, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, values.data()));
    out->close();
}

std::string scene_with(const std::string& object) {
    return R"({"rayo": 1, "camera": {"eye": [0, 6, 9], "look_at": [0, 0, 0], "vfov": 40,
      "width": 96, "height": 72},
      "textures": {"hills": {"type": "perlin", "scale": 2.5, "seed": 3}},
      "materials": {"ground": {"kd": [0.5, 0.7, 0.3], "ks": 0.2}},
      "lights": [{"type": "point", "position": [4, 8, 5]},
                 {"type": "directional", "direction": [1, 1, 0.3], "intensity": 0.5}],
      "objects": [)" +
           object + "]}";
}

std::string error_of(const std::string& text, const std::string& dir = ".") {
    try {
        load_json_string(text, "s.json", dir);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(HeightFieldScene, SixteenBitPngKeepsItsSixteenBits) {
    // A ramp of steps of one 16-bit unit: 8 bits would merge them.
    const int w = 64, h = 3;
    std::vector<float> values;
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) values.push_back(float(1000 + i + 64 * j) / 65535.0f);
    }
    write_image(temp_path("ramp16.png"), w, h, 1, OIIO::TypeDesc::UINT16, values);
    const SceneDescription d = load_json_string(
        scene_with(R"({"type": "heightfield", "image": "ramp16.png", "size": [4, 65535, 2],
                       "method": "dda"})"),
        "s.json", ::testing::TempDir());
    ASSERT_EQ(d.scene.heightfields.size(), 1u);
    const HeightField& f = d.scene.heightfields[0];
    ASSERT_EQ(f.columns, w);
    ASSERT_EQ(f.rows, h);
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) EXPECT_NEAR(f.height(i, j), 1000 + i + 64 * j, 1e-2);
    }
    // The default origin centres the field on x and z, its base at y = 0.
    EXPECT_EQ(f.lower, Vec3(-2.0f, 0.0f, -1.0f));
}

TEST(HeightFieldScene, RgbImagesGiveTheirLuminance) {
    const std::vector<float> rgb = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    write_image(temp_path("rgb.tif"), 2, 2, 3, OIIO::TypeDesc::FLOAT, rgb);
    const SceneDescription d = load_json_string(
        scene_with(R"({"type": "heightfield", "image": "rgb.tif", "size": [1, 2, 1],
                       "origin": [0, 1, 0], "method": "dda"})"),
        "s.json", ::testing::TempDir());
    const HeightField& f = d.scene.heightfields.at(0);
    EXPECT_FLOAT_EQ(f.height(0, 0), 2 * 0.2126f);
    EXPECT_FLOAT_EQ(f.height(1, 0), 2 * 0.7152f);
    EXPECT_FLOAT_EQ(f.height(0, 1), 2 * 0.0722f);
    EXPECT_FLOAT_EQ(f.height(1, 1), 2 * 1.0f);
    EXPECT_EQ(f.bounds().lower, Vec3(0.0f, 1.0f + 2 * 0.0722f, 0.0f));
}

TEST(HeightFieldScene, TraversalAndMeshRenderTheSamePicture) {
    const std::string field =
        R"({"type": "heightfield", "texture": "hills", "resolution": [97, 81],
            "size": [8, 2.5, 6], "smooth": true, "material": "ground", "method": )";
    const SceneDescription dda = load_json_string(scene_with(field + R"("dda"})"), "s.json", ".");
    const SceneDescription mesh = load_json_string(scene_with(field + R"("mesh"})"), "s.json", ".");
    ASSERT_EQ(dda.scene.heightfields.size(), 1u);
    ASSERT_TRUE(dda.scene.meshes.empty());
    ASSERT_TRUE(mesh.scene.heightfields.empty());
    ASSERT_EQ(mesh.scene.meshes.size(), 1u);
    EXPECT_EQ(mesh.scene.meshes[0].triangle_count(), 2u * 96 * 80);
    const Film a = render_scene(dda, 2, false).film, b = render_scene(mesh, 2, false).film;
    int covered = 0, differing = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            covered += a.rgb(x, y) != Vec3(0.0f);
            const Vec3 d = glm::abs(a.rgb(x, y) - b.rgb(x, y));
            differing += std::max(d.x, std::max(d.y, d.z)) > 1e-3f;
        }
    }
    EXPECT_GT(covered, a.width() * a.height() / 4);
    // Pixels may differ only where a shadow ray or a sample grazes an edge: at most 0.5%.
    EXPECT_LE(differing, a.width() * a.height() / 200) << differing << " pixels differ";
}

TEST(HeightFieldScene, AutoChoosesTheMeshForSmallFieldsOnly) {
    const SceneDescription small = load_json_string(
        scene_with(R"({"type": "heightfield", "texture": "hills", "resolution": [65, 65],
                       "size": [8, 1, 8]})"),
        "s.json", ".");
    EXPECT_EQ(small.scene.meshes.size(), 1u);
    EXPECT_TRUE(small.scene.heightfields.empty());
    EXPECT_TRUE(auto_prefers_mesh(64 * 64));
    EXPECT_FALSE(auto_prefers_mesh(4096 * 4096));
}

TEST(HeightFieldScene, BadValuesNameTheirPointer) {
    auto expect_error = [](const std::string& object, const std::string& message,
                           const std::string& dir = ".") {
        const std::string error = error_of(scene_with(object), dir);
        EXPECT_NE(error.find(message), std::string::npos) << error;
    };
    expect_error(R"({"type": "heightfield", "image": "missing.png", "size": [1, 1, 1]})",
                 "s.json#/objects/0/image: cannot open height image 'missing.png'");
    std::ofstream(temp_path("not_an_image.png")) << "hello";
    expect_error(R"({"type": "heightfield", "image": "not_an_image.png", "size": [1, 1, 1]})",
                 "s.json#/objects/0/image: height image '" + temp_path("not_an_image.png") +
                     "' cannot be read",
                 ::testing::TempDir());
    write_image(temp_path("line.png"), 5, 1, 1, OIIO::TypeDesc::UINT8, {0, 0, 0, 0, 0});
    expect_error(R"({"type": "heightfield", "image": "line.png", "size": [1, 1, 1]})",
                 "is 5x1: expected at least 2x2", ::testing::TempDir());
    expect_error(R"({"type": "heightfield", "texture": "hills", "size": [1, 0, 1]})",
                 "s.json#/objects/0/size/1: expected a number > 0, got 0");
    expect_error(R"({"type": "heightfield", "texture": "hills", "size": [-1, 1, 1]})",
                 "s.json#/objects/0/size/0: expected a number > 0, got -1");
    expect_error(R"({"type": "heightfield", "texture": "hills", "size": [1, 1]})",
                 "s.json#/objects/0/size: expected [x, y, z], each > 0");
    expect_error(R"({"type": "heightfield", "texture": "hills"})",
                 "s.json#/objects/0/size: missing required field \"size\"");
    expect_error(
        R"({"type": "heightfield", "texture": "hills", "size": [1, 1, 1], "method": "bvh"})",
        "s.json#/objects/0/method: expected one of \"dda\", \"mesh\", \"auto\"");
    expect_error(R"({"type": "heightfield", "size": [1, 1, 1]})",
                 "s.json#/objects/0: expected exactly one of \"image\"");
    expect_error(R"({"type": "heightfield", "image": "a.png", "texture": "hills",
                     "size": [1, 1, 1]})",
                 "s.json#/objects/0: expected exactly one of \"image\"");
    expect_error(R"({"type": "heightfield", "texture": "rocks", "size": [1, 1, 1]})",
                 "s.json#/objects/0/texture: unknown texture \"rocks\"");
    expect_error(R"({"type": "heightfield", "texture": "hills", "size": [1, 1, 1],
                     "resolution": [1, 4]})",
                 "s.json#/objects/0/resolution/0: expected an integer in [2, 4096]");
    expect_error(R"({"type": "heightfield", "image": "x.png", "size": [1, 1, 1],
                     "resolution": [4, 4]})",
                 "s.json#/objects/0/resolution: resolution applies to \"texture\"");
    expect_error(R"({"type": "heightfield", "texture": "hills", "size": [1, 1, 1],
                     "smooth": 1})",
                 "s.json#/objects/0/smooth: expected true or false");
    expect_error(R"({"type": "heightfield", "texture": "hills", "size": [1, 1, 1], "colour": 1})",
                 "s.json#/objects/0/colour: unknown key");
}

}  // namespace
}  // namespace rayo
