// Textured scenes end to end: a textured sphere against the untextured one, texture tables in
// JSON with errors at their JSON pointers, and the example scenes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "apps/scene/scene_loader.h"
#include "core/error.h"
#include "shading/texture.h"
#include "tests/scene/json_error.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::differing_pixels;
using rayo_test::same_bits;

// A unit sphere filling the view, lit from the camera side.
SceneDescription sphere_scene() {
    SceneDescription d;
    d.source = "<texture test>";
    d.scene.camera.eye = Vec3(0, 0, 4);
    d.scene.camera.look_at = Vec3(0);
    d.scene.camera.vfov_degrees = 35.0f;
    d.scene.camera.width = 64;
    d.scene.camera.height = 64;
    Material m;
    m.kd = Vec3(0.6f);
    m.ks = Vec3(0.3f);
    d.shading.materials.push_back(m);
    d.scene.shapes.of<Sphere>().push_back({Vec3(0), 1.0f, 0});
    PointLight light;
    light.position = Vec3(2, 3, 5);
    d.shading.lights.push_back(light);
    return d;
}

TEST(TextureRender, TexturedSphereDiffersFromUntexturedAndUntexturedIsUnchanged) {
    const SceneDescription plain = sphere_scene();
    const RenderResult base = render_scene(plain, 2, false);

    // A texture table that no material uses changes nothing, bit for bit.
    SceneDescription unused = plain;
    Texture perlin = make_texture("perlin");
    perlin.scale = 0.3f;
    unused.shading.textures.push_back(perlin);
    EXPECT_EQ(differing_pixels(base.film, render_scene(unused, 2, false).film), 0);

    SceneDescription textured = unused;
    textured.shading.materials[0].textures.kd = 0;
    const RenderResult tex = render_scene(textured, 2, false);
    const int sphere_pixels = static_cast<int>(tex.counters.shadow);
    EXPECT_GT(differing_pixels(base.film, tex.film), sphere_pixels / 2);
    EXPECT_EQ(tex.counters.camera, base.counters.camera);
    // Same bits with another thread count.
    EXPECT_EQ(differing_pixels(tex.film, render_scene(textured, 1, false).film), 0);

    SceneDescription bumped = unused;
    bumped.shading.materials[0].textures.bump = 0;
    bumped.shading.materials[0].textures.bump_strength = 0.5f;
    EXPECT_GT(differing_pixels(base.film, render_scene(bumped, 2, false).film), sphere_pixels / 2);

    // A constant bump texture leaves the image as it was.
    SceneDescription flat_bump = plain;
    flat_bump.shading.textures.push_back(make_texture("constant"));
    flat_bump.shading.materials[0].textures.bump = 0;
    EXPECT_EQ(differing_pixels(base.film, render_scene(flat_bump, 2, false).film), 0);
}

// The determinism promise (docs/architecture.md "Hot-path rules": output must not depend on the
// thread count or tile order) for textured scenes, end to end from their JSON: procedural colours
// and bump maps seen directly and through reflection and refraction, antialiased, give the same
// bits with one thread and with two threads over other tile sizes (odd image sizes: partial tiles).
TEST(TextureRender, ExampleScenesGiveTheSameBitsForAnyThreadCountAndTileSize) {
    for (const char* name : {"pool_bottom.json", "marble.json", "cells.json"}) {
        SceneDescription d = load_scene_file(std::string(RAYO_SCENES_DIR) + "/" + name);
        ASSERT_FALSE(d.shading.textures.empty()) << name;
        d.scene.camera.width = 61;
        d.scene.camera.height = 37;
        d.settings.spp = 4;
        d.settings.tile_size = 16;
        const RenderResult one_thread = render_scene(d, 1, false);
        for (int tile : {16, 48, 64}) {
            d.settings.tile_size = tile;
            const RenderResult two_threads = render_scene(d, 2, false);
            EXPECT_TRUE(same_bits(one_thread.film, two_threads.film))
                << name << " tile " << tile << ": "
                << differing_pixels(one_thread.film, two_threads.film) << " pixels differ";
            EXPECT_EQ(two_threads.counters.total_rays(), one_thread.counters.total_rays()) << name;
        }
    }
}

// ---- The "textures" section of JSON scenes -----------------------------------------------

std::string scene_with(const std::string& textures, const std::string& material) {
    return R"({"rayo": 1, "textures": )" + textures + R"(, "materials": {"m": )" + material +
           R"(}, "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1, "material": "m"}]})";
}

std::string load_error(const std::string& text) {
    return json_error_of(text, "t.json");
}

TEST(TextureJson, MaterialsNameTexturesForColoursAndBump) {
    const SceneDescription d = load_json_string(
        scene_with(R"({"stone": {"type": "cellular", "scale": 0.5, "seed": 4, "metric": "manhattan",
                                  "feature": "f2-f1",
                                  "ramp": [{"position": 1, "color": [1, 0, 0]},
                                           {"position": 0, "color": 0.5}]},
                       "ripples": {"type": "perlin", "octaves": 3, "persistence": 0.4}})",
                   R"({"kd": "stone", "ks": "ripples",
                       "bump": {"texture": "ripples", "strength": 0.25}})"),
        "t.json", ".");
    ASSERT_EQ(d.shading.textures.size(), 2u);
    const Texture& stone = d.shading.textures[1];  // name order: ripples, stone
    EXPECT_EQ(stone.name, "stone");
    EXPECT_EQ(stone.scale, 0.5f);
    EXPECT_EQ(stone.seed, 4u);
    EXPECT_EQ(std::get<CellularMap>(stone.map).metric, DistanceMetric::Manhattan);
    EXPECT_EQ(std::get<CellularMap>(stone.map).feature, CellularFeature::F2MinusF1);
    EXPECT_EQ(stone.ramp.eval(0.0f), Vec3(0.5f));
    EXPECT_EQ(stone.ramp.eval(1.0f), Vec3(1, 0, 0));
    EXPECT_EQ(std::get<PerlinMap>(d.shading.textures[0].map).fbm.octaves, 3);
    const Material& m = d.shading.materials[1];
    EXPECT_EQ(m.textures.kd, 1);
    EXPECT_EQ(m.textures.ks, 0);
    EXPECT_EQ(m.textures.ka, 1);  // the default ka = 0.1 × kd follows kd's texture
    EXPECT_FLOAT_EQ(m.textures.ka_scale, 0.1f);
    EXPECT_EQ(m.textures.bump, 0);
    EXPECT_FLOAT_EQ(m.textures.bump_strength, 0.25f);
    EXPECT_FALSE(d.shading.materials[0].textures.any());  // "default" untouched
}

// Every kind of shading/texture.h's list is a JSON texture "type", with that kind's defaults.
TEST(TextureJson, EveryTextureKindIsAType) {
    for (const std::string& kind : texture_kind_names()) {
        const SceneDescription d = load_json_string(
            scene_with(R"({"a": {"type": ")" + kind + R"("}})", R"({})"), "t.json", ".");
        ASSERT_EQ(d.shading.textures.size(), 1u) << kind;
        EXPECT_EQ(d.shading.textures[0].map.index(), make_texture(kind).map.index()) << kind;
    }
    EXPECT_NE(load_error(scene_with(R"({"a": {"type": "plaid"}})", R"({})"))
                  .find("expected one of \"constant\", \"value\""),
              std::string::npos);
}

TEST(TextureJson, ErrorsNameTheJsonPointer) {
    EXPECT_NE(load_error(scene_with(R"({})", R"({"kd": "nope"})"))
                  .find("t.json#/materials/m/kd: unknown texture \"nope\""),
              std::string::npos);
    EXPECT_NE(load_error(scene_with(R"({"a": {"type": "plaid"}})", R"({})"))
                  .find("t.json#/textures/a/type: expected one of"),
              std::string::npos);
    EXPECT_NE(load_error(scene_with(R"({"a": {"type": "perlin", "octaves": 40}})", R"({})"))
                  .find("t.json#/textures/a/octaves: expected an integer in [1, 16]"),
              std::string::npos);
    EXPECT_NE(load_error(scene_with(R"({"a": {"type": "perlin", "scale": 0}})", R"({})"))
                  .find("t.json#/textures/a/scale"),
              std::string::npos);
    EXPECT_NE(load_error(scene_with(R"({"a": {"type": "cellular", "warp": 1}})", R"({})"))
                  .find("t.json#/textures/a/warp: unknown key"),
              std::string::npos);
    EXPECT_NE(load_error(scene_with(R"({"a": {"type": "value", "ramp": []}})", R"({})"))
                  .find("t.json#/textures/a/ramp: expected a non-empty array"),
              std::string::npos);
    EXPECT_NE(load_error(scene_with(R"({"a": {"type": "value",
                                               "ramp": [{"position": 0, "color": -1}]}})",
                                    R"({})"))
                  .find("t.json#/textures/a/ramp/0/color"),
              std::string::npos);
    EXPECT_NE(load_error(scene_with(R"({"a": {"type": "value"}})",
                                    R"({"bump": {"texture": "a", "strength": "x"}})"))
                  .find("t.json#/materials/m/bump/strength: expected a number"),
              std::string::npos);
    EXPECT_NE(load_error(scene_with(R"({"a": {"type": "value"}})", R"({"bump": {"strength": 1}})"))
                  .find("t.json#/materials/m/bump/texture: missing required field"),
              std::string::npos);
}

// The example scenes load and render: textured objects differ from their untextured selves.
TEST(TextureJson, ExampleScenesLoadAndRender) {
    for (const char* name : {"pool_bottom.json", "marble.json", "cells.json"}) {
        SceneDescription d = load_scene_file(std::string(RAYO_SCENES_DIR) + "/" + name);
        ASSERT_FALSE(d.shading.textures.empty()) << name;
        d.scene.camera.width = 48;
        d.scene.camera.height = 32;
        const RenderResult textured = render_scene(d, 2, false);
        for (Material& m : d.shading.materials) m.textures = MaterialTextures{};
        const RenderResult plain = render_scene(d, 2, false);
        EXPECT_GT(differing_pixels(textured.film, plain.film), 48 * 32 / 4) << name;
    }
}
}  // namespace
}  // namespace rayo
