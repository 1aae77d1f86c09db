// Solid textures (seed 003 ch. 3): colour ramps, every named kind in range and deterministic, the
// pool-bottom preset within its water ramp, bump mapping, and end-to-end renders of a textured
// sphere against the untextured one.
#include "shading/texture.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>

#include "apps/cli.h"
#include "apps/json_loader.h"
#include "apps/renderer.h"
#include "apps/scene_loader.h"
#include "core/error.h"

namespace rayo {
namespace {

Vec3 point(int i, float extent) {
    const uint32_t h = hash_u32(static_cast<uint32_t>(i) * 104729u + 3u);
    return Vec3((unit_float(h) - 0.5f) * 2 * extent,
                (unit_float(hash_u32(h + 1)) - 0.5f) * 2 * extent,
                (unit_float(hash_u32(h + 2)) - 0.5f) * 2 * extent);
}

TEST(TextureRamp, InterpolatesBetweenAnyNumberOfSortedStops) {
    const ColorRamp ramp({{1.0f, Vec3(0, 0, 1)}, {0.0f, Vec3(1, 0, 0)}, {0.5f, Vec3(0, 1, 0)}});
    ASSERT_EQ(ramp.stops().size(), 3u);
    EXPECT_EQ(ramp.stops()[1].position, 0.5f);  // sorted
    EXPECT_EQ(ramp.eval(0.0f), Vec3(1, 0, 0));
    EXPECT_EQ(ramp.eval(0.5f), Vec3(0, 1, 0));
    EXPECT_EQ(ramp.eval(1.0f), Vec3(0, 0, 1));
    const Vec3 quarter = ramp.eval(0.25f);
    EXPECT_FLOAT_EQ(quarter.x, 0.5f);
    EXPECT_FLOAT_EQ(quarter.y, 0.5f);
    EXPECT_FLOAT_EQ(quarter.z, 0.0f);
    EXPECT_EQ(ramp.eval(-3.0f), Vec3(1, 0, 0));  // beyond the ends: the end colours
    EXPECT_EQ(ramp.eval(7.0f), Vec3(0, 0, 1));
    EXPECT_EQ(ramp.eval(std::nanf("")), Vec3(1, 0, 0));
    const ColorRamp single({{0.3f, Vec3(0.2f)}});
    EXPECT_EQ(single.eval(0.9f), Vec3(0.2f));
    EXPECT_THROW(ColorRamp(std::vector<ColorStop>{}), std::invalid_argument);
    // A hard step: two stops at the same position.
    const ColorRamp step({{0.5f, Vec3(0.0f)}, {0.5f, Vec3(1.0f)}});
    EXPECT_EQ(step.eval(0.49f), Vec3(0.0f));
    EXPECT_EQ(step.eval(0.51f), Vec3(1.0f));
}

TEST(TextureRamp, SrgbDecoding) {
    EXPECT_EQ(srgb8_to_linear(0), 0.0f);
    EXPECT_FLOAT_EQ(srgb8_to_linear(255), 1.0f);
    EXPECT_NEAR(srgb8_to_linear(128), 0.2158605f, 1e-6f);
    EXPECT_NEAR(srgb8_to_linear(10), 10.0f / 255.0f / 12.92f, 1e-7f);
}

TEST(TextureKinds, EveryKindIsFiniteInRangeAndInsideItsRamp) {
    for (const std::string& kind : texture_kind_names()) {
        Texture t = make_texture(kind);
        t.scale = 0.7f;
        Vec3 lo(1e9f), hi(-1e9f);
        for (const ColorStop& s : t.ramp.stops()) {
            lo = glm::min(lo, s.color);
            hi = glm::max(hi, s.color);
        }
        float vmin = 1e9f, vmax = -1e9f;
        for (int i = 0; i < 3000; ++i) {
            const Vec3 p = point(i, 300.0f);
            const float v = t.value(p);
            ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << kind << " " << v;
            vmin = std::min(vmin, v);
            vmax = std::max(vmax, v);
            const Vec3 c = t.color(p);
            if (kind == "constant") {
                ASSERT_EQ(c, std::get<ConstantMap>(t.map).color);
                continue;
            }
            for (int k = 0; k < 3; ++k) {
                ASSERT_GE(c[k], lo[k] - 1e-6f) << kind;
                ASSERT_LE(c[k], hi[k] + 1e-6f) << kind;
            }
        }
        if (kind != "constant") {
            EXPECT_GT(vmax - vmin, 0.3f) << kind << " barely varies";
        }
    }
    EXPECT_THROW(make_texture("plaid"), InputError);
}

TEST(TextureKinds, PoolBottomUsesTheSeedsWaterRampAndStaysInIt) {
    const Texture t = make_texture("pool-bottom");
    ASSERT_EQ(t.ramp.stops().size(), 2u);
    const Vec3 dark = srgb8_to_linear(40, 100, 162), light = srgb8_to_linear(91, 187, 201);
    EXPECT_EQ(t.ramp.stops().front().color, dark);
    EXPECT_EQ(t.ramp.stops().back().color, light);
    double sum = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const Vec3 p = point(i, 40.0f);
        const Vec3 c = t.color(p);
        for (int k = 0; k < 3; ++k) {
            ASSERT_GE(c[k], dark[k] - 1e-6f);
            ASSERT_LE(c[k], light[k] + 1e-6f);
        }
        sum += t.value(p);
    }
    // Squared maps in [0, 1] mixed 0.3/0.7: mostly dark water with bright cell edges.
    EXPECT_GT(sum / n, 0.1);
    EXPECT_LT(sum / n, 0.6);
}

TEST(TextureKinds, ScaleAndSeed) {
    Texture a = make_texture("perlin");
    Texture b = a;
    b.scale = 2.0f;
    for (int i = 0; i < 200; ++i) {
        const Vec3 p = point(i, 10.0f);
        EXPECT_EQ(a.value(p), b.value(2.0f * p));
    }
    Texture c = a;
    c.seed = 99;
    int differ = 0;
    for (int i = 0; i < 200; ++i) differ += a.value(point(i, 10.0f)) != c.value(point(i, 10.0f));
    EXPECT_GE(differ, 195);
}

TEST(TextureKinds, ParallelEvaluationEqualsSerial) {
    for (const std::string& kind : texture_kind_names()) {
        const Texture t = make_texture(kind);
        const int n = 4000;
        std::vector<Vec3> serial(n), parallel(n);
        for (int i = 0; i < n; ++i) serial[i] = t.color(point(i, 20.0f));
        tbb::parallel_for(0, n, [&](int i) { parallel[i] = t.color(point(i, 20.0f)); });
        for (int i = 0; i < n; ++i) ASSERT_EQ(serial[i], parallel[i]) << kind << " " << i;
    }
}

// Marble without distortion is 0.5 + 0.5·sin(2π·f·x/scale): its gradient is known.
TEST(TextureBump, GradientMatchesTheAnalyticDerivative) {
    Texture t = make_texture("marble");
    auto& m = std::get<MarbleMap>(t.map);
    m.distortion = 0.0f;
    m.frequency = 0.5f;
    t.scale = 2.0f;
    for (float x = -3.0f; x < 3.0f; x += 0.37f) {
        const Vec3 g = t.gradient(Vec3(x, 0.2f, -1.1f));
        const float k = 2.0f * kPi * m.frequency / t.scale;
        EXPECT_NEAR(g.x, 0.5f * k * std::cos(k * x), 2e-3f) << x;
        EXPECT_NEAR(g.y, 0.0f, 1e-6f);
        EXPECT_NEAR(g.z, 0.0f, 1e-6f);
    }
    EXPECT_EQ(make_texture("constant").gradient(Vec3(1.0f)), Vec3(0.0f));
}

TEST(TextureBump, PerturbsOnlyByTheTangentialGradient) {
    const Vec3 n(0, 0, 1);
    EXPECT_EQ(perturb_normal(n, Vec3(0.0f), 5.0f, n), n);        // flat texture
    EXPECT_EQ(perturb_normal(n, Vec3(0, 0, 3.0f), 5.0f, n), n);  // varies only along n
    EXPECT_EQ(perturb_normal(n, Vec3(1, 0, 0), 0.0f, n), n);     // no strength
    const Vec3 tilted = perturb_normal(n, Vec3(1, 0, 0), 1.0f, n);
    EXPECT_NEAR(glm::length(tilted), 1.0f, 1e-6f);
    EXPECT_NEAR(tilted.x, -std::sqrt(0.5f), 1e-6f);  // normalize(n − ∇): leans away from uphill
    EXPECT_NEAR(tilted.z, std::sqrt(0.5f), 1e-6f);
    // However strong the bump, the normal stays on the geometric normal's side.
    const Vec3 steep = perturb_normal(n, Vec3(1, 0, 0), 1e6f, n);
    EXPECT_GT(glm::dot(steep, n), 0.0f);
    EXPECT_NEAR(glm::length(steep), 1.0f, 1e-5f);
    const Vec3 not_finite = perturb_normal(n, Vec3(INFINITY, 0, 0), 1.0f, n);
    EXPECT_EQ(not_finite, n);
}

TEST(TextureBump, ChangesTheNormalOnlyWhereTheTextureVaries) {
    Texture stripes = make_texture("marble");  // varies along x only
    std::get<MarbleMap>(stripes.map).distortion = 0.0f;
    const Texture flat = make_texture("constant");
    int changed_across = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec3 p = point(i, 5.0f);
        // A surface facing x: the texture is constant along it, so the normal must not move.
        const Vec3 nx(1, 0, 0);
        const Vec3 bx = bump_normal(stripes, 1.0f, p, nx, nx);
        EXPECT_NEAR(bx.x, 1.0f, 1e-6f);
        EXPECT_NEAR(bx.y, 0.0f, 1e-4f);
        EXPECT_NEAR(bx.z, 0.0f, 1e-4f);
        // A surface facing y sees the stripes vary across it.
        const Vec3 ny(0, 1, 0);
        changed_across += glm::dot(bump_normal(stripes, 1.0f, p, ny, ny), ny) < 0.999f;
        EXPECT_EQ(bump_normal(flat, 1.0f, p, ny, ny), ny);
    }
    EXPECT_GT(changed_across, 150);
}

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
    d.scene.spheres.push_back({Vec3(0), 1.0f, 0});
    PointLight light;
    light.position = Vec3(2, 3, 5);
    d.shading.lights.push_back(light);
    return d;
}

int differing_pixels(const Film& a, const Film& b) {
    int n = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) n += a.rgb(x, y) != b.rgb(x, y);
    }
    return n;
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

// ---- The "textures" section of JSON scenes -----------------------------------------------

std::string scene_with(const std::string& textures, const std::string& material) {
    return R"({"rayo": 1, "textures": )" + textures + R"(, "materials": {"m": )" + material +
           R"(}, "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1, "material": "m"}]})";
}

std::string load_error(const std::string& text) {
    try {
        load_json_string(text, "t.json", ".");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
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

// ---- `rayo texture NAME` ---------------------------------------------------------------------

int cli(std::vector<std::string> args, std::string* err_text = nullptr) {
    args.insert(args.begin(), "rayo");
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    std::ostringstream out, err;
    const int rc = run_cli(static_cast<int>(argv.size()), argv.data(), out, err);
    if (err_text) *err_text = err.str();
    return rc;
}

TEST(TextureCli, WritesTheTextureFlatAndRefusesBadFlags) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("rayo_texture_cli_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string exr = (dir / "pool.exr").string();
    ASSERT_EQ(cli({"texture", "pool-bottom", "-o", exr, "--size", "40x24", "--seed", "3"}), 0);
    auto in = OIIO::ImageInput::open(exr);
    ASSERT_TRUE(in);
    const OIIO::ImageSpec& spec = in->spec();
    ASSERT_EQ(spec.width, 40);
    ASSERT_EQ(spec.height, 24);
    std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    in->close();
    // Exactly the texture's colours at the pixel centres of the plane z = 0, 64 px per unit.
    Texture t = make_texture("pool-bottom");
    t.seed = 3;
    for (int j = 0; j < 24; j += 5) {
        for (int i = 0; i < 40; i += 7) {
            const Vec3 c = t.color(Vec3((i + 0.5f) / 64.0f, (24 - j - 0.5f) / 64.0f, 0.0f));
            const float* p = &pixels[(static_cast<size_t>(j) * 40 + i) * spec.nchannels];
            EXPECT_FLOAT_EQ(p[0], c.x);
            EXPECT_FLOAT_EQ(p[1], c.y);
            EXPECT_FLOAT_EQ(p[2], c.z);
        }
    }
    for (const char* name : {"perlin", "cellular", "marble"}) {
        EXPECT_EQ(cli({"texture", name, "-o", (dir / (std::string(name) + ".png")).string(),
                       "--size", "16x16", "--scale", "0.5"}),
                  0)
            << name;
    }
    std::string err;
    EXPECT_EQ(cli({"texture", "plaid"}, &err), 2);
    EXPECT_NE(err.find("pool-bottom"), std::string::npos);
    EXPECT_EQ(cli({"texture"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--size", "16"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--size", "0x16"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--scale", "inf"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--scale", "0"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--seed", "-1"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--bogus"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "-o", (dir / "x.unknown").string()}), 1);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rayo
