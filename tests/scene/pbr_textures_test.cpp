// glTF's metallic-roughness and occlusion textures and emission images on the mesh light
// (docs/models.md, "Metallic, roughness, occlusion and emission textures"), with the images
// written by the test: a quad whose metallicRoughnessTexture is metal in one half and a rough
// dielectric in the other shades like the two factor-only materials; occlusion darkens the
// ambient term only; an emitter whose emissiveTexture is black in one half lights the floor
// under its bright half only, as much as a light of that half alone; MTL map_Ke.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "apps/scene/model_scene.h"
#include "apps/scene/renderer.h"
#include "core/error.h"
#include "shading/light.h"
#include "tests/scene/gltf_test_writer.h"
#include "tests/scene/scene_test_files.h"

namespace rayo {
namespace {

using Json = nlohmann::json;
using rayo_test::TempDir;

// A w × 16 RGB PNG: the colour `left` in its left half, `right` in its right half.
void write_halves(const std::string& path, const std::array<unsigned char, 3>& left,
                  const std::array<unsigned char, 3>& right, int w = 32) {
    const int h = 16;
    std::vector<unsigned char> pixels(static_cast<size_t>(w * h * 3));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            std::memcpy(&pixels[static_cast<size_t>((y * w + x) * 3)],
                        (x < w / 2 ? left : right).data(), 3);
        }
    }
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
    out->close();
}

// A glTF file of quads with texture coordinates (one data-URI buffer), each with its material
// (JSON as the file has it); every texture is an image file beside it.
struct QuadsGltf {
    rayo_test::GltfTestWriter g;

    // Corners a, b, c, d (counter-clockwise seen from the side it faces) with coordinates uv.
    void quad(const std::array<Vec3, 4>& corners, const std::array<glm::vec2, 4>& uv,
              const Json& material) {
        std::vector<float> xyz, st;
        for (const Vec3& c : corners) xyz.insert(xyz.end(), {c.x, c.y, c.z});
        for (const glm::vec2& t : uv) st.insert(st.end(), {t.x, t.y});
        const int position = g.positions(xyz);
        const int texcoord = g.accessor(st, "VEC2");
        const int index = g.indices({0, 1, 2, 0, 2, 3}, 5125);
        const Json primitive = {{"attributes", {{"POSITION", position}, {"TEXCOORD_0", texcoord}}},
                                {"indices", index},
                                {"material", g.push("materials", material)}};
        g.node({{"mesh", g.mesh(primitive)}});
    }
    // A texture of the image file `uri`, clamped to its edges (with the default REPEAT the
    // filter would mix the opposite edge in); its index.
    int texture(const std::string& uri) {
        g.doc()["samplers"] = Json::array({Json{{"wrapS", 33071}, {"wrapT", 33071}}});
        return g.push("textures", {{"source", g.push("images", {{"uri", uri}})}, {"sampler", 0}});
    }
    std::string write(const TempDir& dir, const std::string& name) {
        return g.write_embedded(dir, name);
    }
};

Json pbr_material(const Vec3& base, double metallic, double roughness) {
    return {{"pbrMetallicRoughness",
             {{"baseColorFactor", {base.x, base.y, base.z, 1.0}},
              {"metallicFactor", metallic},
              {"roughnessFactor", roughness}}}};
}

// The unit quad (0,0,0)-(1,1,0) facing +z, the image's top at y = 1 (u = x, v = 1 − y).
void unit_quad(QuadsGltf& g, const Json& material) {
    g.quad({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)},
           {glm::vec2(0, 1), glm::vec2(1, 1), glm::vec2(1, 0), glm::vec2(0, 0)}, material);
}

SceneDescription load(const std::string& path) {
    ModelFraming framing;
    framing.ground = false;
    return load_model_scene(path, framing);
}

// The radiance a camera ray from `eye` toward the point `p` brings (a 1-pixel render with a
// narrow field of view, as the integrator shades through a render).
Vec3 seen(SceneDescription d, const Vec3& p, const Vec3& eye, const Vec3& up) {
    d.scene.camera.eye = eye;
    d.scene.camera.look_at = p;
    d.scene.camera.up = up;
    d.scene.camera.vfov_degrees = 0.05f;
    d.scene.camera.width = d.scene.camera.height = 1;
    return render_scene(d, 1, false).film.rgb(0, 0);
}

// The quad head-on from +z under a tilted directional light (the highlight's exponent
// matters), an ambient light and a coloured background its mirror weight reflects.
Vec3 shaded_quad(SceneDescription d, float x, float y) {
    DirectionalLight light;
    light.direction = glm::normalize(Vec3(-0.3f, 0.1f, -1.0f));
    d.shading.lights = {Light(light)};
    d.shading.ambient_light = Vec3(0.2f);
    d.shading.background = Vec3(0.3f, 0.6f, 0.9f);
    return seen(d, Vec3(x, y, 0.0f), Vec3(x, y, 3.0f), Vec3(0, 1, 0));
}

void expect_near(const Vec3& actual, const Vec3& expected, float tolerance, const char* what) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

const Vec3 kBase(0.8f, 0.5f, 0.2f);

// The factor-only material with metallic m and roughness r, shaded as shaded_quad does.
Vec3 factor_only(float m, float r) {
    const TempDir dir;
    QuadsGltf g;
    unit_quad(g, pbr_material(kBase, m, r));
    return shaded_quad(load(g.write(dir, "plain.gltf")), 0.5f, 0.5f);
}

TEST(PbrTextures, MetallicRoughnessTextureMakesOneHalfMetalAndTheOtherDielectric) {
    const TempDir dir;
    // Left: B = 255 (metal), G = 0 (smooth); right: B = 0 (dielectric), G = 128: linear
    // 128/255 (an sRGB decode would give 0.216), R unused.
    write_halves(dir.file("mr.png"), {77, 0, 255}, {200, 128, 0});
    QuadsGltf g;
    Json material = pbr_material(kBase, 0.6, 0.5);
    material["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {{"index", g.texture("mr.png")}};
    unit_quad(g, material);
    const SceneDescription d = load(g.write(dir, "mr.gltf"));
    EXPECT_TRUE(d.warnings.empty());
    // The texel times the factors: metallic 0.6·1, roughness 0.5·0 on the left; metallic 0,
    // roughness 0.5·128/255 on the right.
    const Vec3 metal = factor_only(0.6f, 0.0f);
    const Vec3 dielectric = factor_only(0.0f, 0.5f * 128.0f / 255.0f);
    expect_near(shaded_quad(d, 0.25f, 0.5f), metal, 2e-4f, "metal half");
    expect_near(shaded_quad(d, 0.75f, 0.5f), dielectric, 2e-4f, "dielectric half");
    // And they differ: the metal shows the base colour in its highlight and mirror.
    EXPECT_GT(glm::length(metal - dielectric), 0.1f);
}

TEST(PbrTextures, OcclusionTextureDarkensTheAmbientTermOnly) {
    const TempDir dir;
    // R = 0 on the left, 255 on the right; G and B the other way round (only R counts).
    write_halves(dir.file("ao.png"), {0, 255, 255}, {255, 0, 0});
    QuadsGltf g;
    Json material = pbr_material(Vec3(0.5f), 0.0, 1.0);
    material["occlusionTexture"] = {{"index", g.texture("ao.png")}, {"strength", 0.5}};
    unit_quad(g, material);
    SceneDescription d = load(g.write(dir, "ao.gltf"));
    EXPECT_TRUE(d.warnings.empty());
    d.shading.background = Vec3(0.0f);
    // Ambient light alone: ka·Ia·(1 + 0.5·(R − 1)): half on the left.
    SceneDescription ambient = d;
    ambient.shading.lights.clear();
    ambient.shading.ambient_light = Vec3(1.0f);
    const Vec3 left = seen(ambient, Vec3(0.25f, 0.5f, 0), Vec3(0.25f, 0.5f, 3), Vec3(0, 1, 0));
    const Vec3 right = seen(ambient, Vec3(0.75f, 0.5f, 0), Vec3(0.75f, 0.5f, 3), Vec3(0, 1, 0));
    expect_near(right, Vec3(0.05f), 1e-5f, "unoccluded: ka = 0.1·base");
    expect_near(left, 0.5f * right, 1e-5f, "occluded, strength 0.5");
    // A light alone: no difference.
    SceneDescription direct = d;
    DirectionalLight light;
    light.direction = Vec3(0.0f, 0.0f, -1.0f);
    direct.shading.lights = {Light(light)};
    direct.shading.ambient_light = Vec3(0.0f);
    const Vec3 lit_left = seen(direct, Vec3(0.25f, 0.5f, 0), Vec3(0.25f, 0.5f, 3), Vec3(0, 1, 0));
    const Vec3 lit_right = seen(direct, Vec3(0.75f, 0.5f, 0), Vec3(0.75f, 0.5f, 3), Vec3(0, 1, 0));
    EXPECT_GT(lit_right.x, 0.1f);
    expect_near(lit_left, lit_right, 1e-6f, "direct light");
}

TEST(PbrTextures, OcclusionStrengthOutsideZeroToOneIsRefused) {
    const TempDir dir;
    write_halves(dir.file("ao.png"), {0, 0, 0}, {255, 255, 255});
    QuadsGltf g;
    Json material = pbr_material(Vec3(0.5f), 0.0, 1.0);
    material["name"] = "stone";
    material["occlusionTexture"] = {{"index", g.texture("ao.png")}, {"strength", 1.5}};
    unit_quad(g, material);
    const std::string path = g.write(dir, "bad.gltf");
    try {
        load(path);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("bad.gltf"), std::string::npos) << what;
        EXPECT_NE(what.find("material 'stone': occlusionTexture.strength must be in [0, 1]"),
                  std::string::npos)
            << what;
    }
}

// A floor (y = 0, ±2) under a square emitter (y = 1, x and z in ±1) facing down; the emitter's
// emissiveTexture is `texture` ("" for none) over u = (x + 1)/2, v = (z + 1)/2. `half` keeps
// only the emitter's x ≥ 0 half, untextured.
SceneDescription lit_floor(const TempDir& dir, const std::string& texture, bool half = false) {
    QuadsGltf g;
    g.quad({Vec3(-2, 0, -2), Vec3(-2, 0, 2), Vec3(2, 0, 2), Vec3(2, 0, -2)},
           {glm::vec2(0, 0), glm::vec2(0, 1), glm::vec2(1, 1), glm::vec2(1, 0)},
           pbr_material(Vec3(1.0f), 0.0, 1.0));
    Json emitter = pbr_material(Vec3(0.0f), 0.0, 1.0);
    emitter["emissiveFactor"] = {2.0, 2.0, 2.0};
    if (!texture.empty()) emitter["emissiveTexture"] = {{"index", g.texture(texture)}};
    const float x0 = half ? 0.0f : -1.0f;
    g.quad({Vec3(x0, 1, -1), Vec3(1, 1, -1), Vec3(1, 1, 1), Vec3(x0, 1, 1)},
           {glm::vec2(0.5f * (x0 + 1), 0), glm::vec2(1, 0), glm::vec2(1, 1),
            glm::vec2(0.5f * (x0 + 1), 1)},
           emitter);
    SceneDescription d = load(g.write(dir, "floor.gltf"));
    EXPECT_TRUE(d.warnings.empty());
    EXPECT_EQ(d.shading.lights.size(), 1u);  // the emitter; no automatic lights
    // Many samples: the comparison below is between two estimates of the same integral.
    for (Light& light : d.shading.lights) std::get<AreaLight>(light).samples = 1024;
    d.shading.ambient_light = Vec3(0.0f);
    return d;
}

float floor_light(const SceneDescription& d, float x, float z) {
    const Vec3 p(x, 0.0f, z);
    return seen(d, p, p + Vec3(0.0f, 0.5f, 0.0f), Vec3(0, 0, 1)).y;
}

TEST(PbrTextures, EmissiveTextureShapesTheLightOfTheMeshEmitter) {
    const TempDir dir;
    // u < 0.5 (x < 0) black; 256 texels wide, so that the filtered edge between the halves
    // (a few texels, filtered on sRGB-encoded values: darker than the mean) is a thin strip.
    write_halves(dir.file("half.png"), {0, 0, 0}, {255, 255, 255}, 256);
    const SceneDescription textured = lit_floor(dir, "half.png");
    const SceneDescription uniform = lit_floor(dir, "");
    const SceneDescription half = lit_floor(dir, "", true);
    // The uniform light lights both sides alike; the textured one the side under its white
    // half more.
    EXPECT_NEAR(floor_light(uniform, -0.6f, 0.0f), floor_light(uniform, 0.6f, 0.0f),
                0.03f * floor_light(uniform, 0.6f, 0.0f));
    EXPECT_LT(floor_light(textured, -0.6f, 0.0f), 0.6f * floor_light(textured, 0.6f, 0.0f));
    // Unbiased: the textured light gives what a light of its white half alone gives (samples
    // on the black half bring nothing; the pick and the pdf stay those of the whole square).
    for (const float x : {-1.2f, -0.6f, 0.0f, 0.6f, 1.2f}) {
        const float expected = floor_light(half, x, 0.3f);
        EXPECT_GT(expected, 0.0f);
        EXPECT_NEAR(floor_light(textured, x, 0.3f), expected, 0.03f * expected) << "x " << x;
    }
}

// MTL map_Ke multiplies Ke (sRGB), as the glTF emissive texture multiplies its factor.
TEST(PbrTextures, MtlMapKeMultipliesKe) {
    const TempDir dir;
    write_halves(dir.file("ke.png"), {0, 0, 0}, {255, 255, 255});
    dir.write("quad.obj",
              "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
              "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl glow\nf 1/1 2/2 3/3 4/4\n");
    dir.write("quad.mtl", "newmtl glow\nKa 0 0 0\nKd 0 0 0\nKs 0 0 0\nKe 2 1 0.5\nmap_Ke ke.png\n");
    SceneDescription d = load(dir.file("quad.obj"));
    EXPECT_TRUE(d.warnings.empty());
    d.shading.ambient_light = Vec3(0.0f);
    expect_near(seen(d, Vec3(0.25f, 0.5f, 0), Vec3(0.25f, 0.5f, 3), Vec3(0, 1, 0)), Vec3(0.0f),
                1e-6f, "black half");
    expect_near(seen(d, Vec3(0.75f, 0.5f, 0), Vec3(0.75f, 0.5f, 3), Vec3(0, 1, 0)),
                Vec3(2.0f, 1.0f, 0.5f), 1e-4f, "white half");
}

}  // namespace
}  // namespace rayo
