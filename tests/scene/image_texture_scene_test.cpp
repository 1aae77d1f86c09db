// Image textures end to end (docs/textures.md, "Image textures"): a quad with a two-colour
// checker PNG written by the test (OpenImageIO ImageOutput), loaded through OBJ+MTL, glTF (a data
// URI buffer, the PNG beside it) and JSON, shaded where the checker's cells are known: the
// texels sRGB-decoded, the texture transform applied, missing textures a warning, bad JSON
// images refused with their pointer, the cache reported.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/accel.h"
#include "core/error.h"
#include "shading/integrators/whitted.h"
#include "tests/scene/gltf_test_writer.h"
#include "tests/scene/json_error.h"
#include "tests/scene/scene_test_files.h"

namespace rayo {
namespace {

using Json = nlohmann::json;
using rayo_test::TempDir;

// The checker: 3 columns × 2 rows of 16-texel cells, colour A where column + row is even (the
// top-left cell), B elsewhere. Not symmetric under a flip of either axis or a transpose.
constexpr int kCell = 16, kColumns = 3, kRows = 2;
const unsigned char kA[3] = {230, 30, 30};
const unsigned char kB[3] = {30, 30, 230};

void write_checker(const std::string& path) {
    const int w = kColumns * kCell, h = kRows * kCell;
    std::vector<unsigned char> pixels(static_cast<size_t>(w * h * 3));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const unsigned char* c = ((x / kCell + y / kCell) % 2 == 0) ? kA : kB;
            std::memcpy(&pixels[static_cast<size_t>((y * w + x) * 3)], c, 3);
        }
    }
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
    out->close();
}

// sRGB byte -> linear, written out here independently of the code under test (IEC 61966-2-1).
float decoded(unsigned char byte) {
    const double c = byte / 255.0;
    return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}
Vec3 linear(const unsigned char* c) {
    return Vec3(decoded(c[0]), decoded(c[1]), decoded(c[2]));
}

// The quad (0,0,0)-(1,1,0) seen from +z, lit head-on by a directional light of intensity 1,
// no ambient light: its radiance at world (x, y).
struct QuadScene {
    SceneDescription d;
    Vec3 at(float x, float y) const {
        const Accel accel(d.scene, AccelOptions{});
        ImageTextures images(d.shading.materials, kDefaultTextureCacheMB);
        const WhittedIntegrator integrator(accel, d.shading, d.settings.whitted(), nullptr,
                                           &images);
        Ray ray;
        ray.origin = Vec3(x, y, 5.0f);
        ray.direction = Vec3(0.0f, 0.0f, -1.0f);
        RayCounters counters;
        return integrator.radiance(ray, counters);
    }
};

QuadScene quad_scene(const TempDir& dir, const std::string& mesh_file,
                     const std::string& extra_materials = "") {
    QuadScene s;
    s.d = load_json_string(R"({"rayo": 1, "ambient_light": 0,)" + extra_materials + R"(
        "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1}],
        "objects": [{"type": "mesh", "file": ")" +
                               mesh_file + R"("}]})",
                           dir.file("scene.json"), dir.path());
    return s;
}

// World (x, y) at the centre of checker cell (column, row); row 0 is the image's top, which
// the quads put at y = 1.
float cell_x(int column) {
    return (column + 0.5f) / kColumns;
}
float cell_y(int row) {
    return 1.0f - (row + 0.5f) / kRows;
}
const unsigned char* cell_colour(int column, int row) {
    return (column + row) % 2 == 0 ? kA : kB;
}

void expect_near(const Vec3& actual, const Vec3& expected, float tolerance, const char* where) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << where;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << where;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << where;
}

const char* const kQuadObj =
    "mtllib quad.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "usemtl checker\nf 1/1 2/2 3/3 4/4\n";

TEST(ImageTextureScene, ObjMapKdShowsTheCheckerDecodedFromSrgb) {
    const TempDir dir;
    write_checker(dir.file("checker.png"));
    dir.write("quad.obj", kQuadObj);
    dir.write("quad.mtl", "newmtl checker\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nmap_Kd checker.png\n");
    const QuadScene s = quad_scene(dir, "quad.obj");
    EXPECT_TRUE(s.d.warnings.empty());
    for (int row = 0; row < kRows; ++row) {
        for (int column = 0; column < kColumns; ++column) {
            const std::string where = "cell " + std::to_string(column) + "," + std::to_string(row);
            // kd = Kd·texel, the light's cosine is 1: the decoded texel itself (not the byte/255
            // of an undecoded image: 230/255 = 0.90 against 0.79).
            expect_near(s.at(cell_x(column), cell_y(row)), linear(cell_colour(column, row)), 1e-3f,
                        where.c_str());
        }
    }
}

TEST(ImageTextureScene, MapKdMultipliesKdAndMtlOptionsScaleTheCoordinates) {
    const TempDir dir;
    write_checker(dir.file("checker.png"));
    dir.write("quad.obj", kQuadObj);
    // -o 0.3333333 shifts s by one column: every cell shows its neighbour's colour.
    dir.write(
        "quad.mtl",
        "newmtl checker\nKa 0 0 0\nKd 0.5 1 1\nKs 0 0 0\nmap_Kd -o 0.3333333 0 0 checker.png\n");
    const QuadScene s = quad_scene(dir, "quad.obj");
    const Vec3 b = linear(kB);
    expect_near(s.at(cell_x(0), cell_y(0)), Vec3(0.5f * b.x, b.y, b.z), 1e-3f, "cell 0,0");
}

TEST(ImageTextureScene, MissingMapKdIsAWarningNamingFileAndMaterial) {
    const TempDir dir;
    dir.write("quad.obj", kQuadObj);
    dir.write("quad.mtl", "newmtl checker\nKa 0 0 0\nKd 0.25 0.5 1\nKs 0 0 0\nmap_Kd gone.png\n");
    const QuadScene s = quad_scene(dir, "quad.obj");
    ASSERT_EQ(s.d.warnings.size(), 1u);
    EXPECT_NE(s.d.warnings[0].find("gone.png"), std::string::npos) << s.d.warnings[0];
    EXPECT_NE(s.d.warnings[0].find("material 'checker'"), std::string::npos) << s.d.warnings[0];
    // Shaded with Kd alone.
    expect_near(s.at(0.5f, 0.5f), Vec3(0.25f, 0.5f, 1.0f), 1e-5f, "centre");
}

// A glTF quad whose TEXCOORD_0 puts the image's top at y = 1, with a data-URI buffer and the
// checker PNG beside it; `texture_info` is its baseColorTexture.
std::string write_gltf_quad(const TempDir& dir, const Json& texture_info,
                            const Json& base_colour = Json::array({1.0, 1.0, 1.0, 1.0})) {
    rayo_test::GltfTestWriter g;
    const int position = g.positions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
    const int uv = g.accessor({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2");
    const int index = g.indices({0, 1, 2, 0, 2, 3});
    Json material = {
        {"name", "checker"},
        {"pbrMetallicRoughness",
         {{"baseColorFactor", base_colour}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}}};
    if (!texture_info.is_null())
        material["pbrMetallicRoughness"]["baseColorTexture"] = texture_info;
    g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", position}, {"TEXCOORD_0", uv}}},
                             {"indices", index},
                             {"material", g.push("materials", material)}})}});
    g.doc()["textures"] = {{{"source", 0}, {"sampler", 0}}};
    g.doc()["samplers"] = {{{"wrapS", 10497}, {"wrapT", 10497}}};
    g.doc()["images"] = {{{"uri", "checker.png"}}};
    return g.write_embedded(dir, "quad.gltf");
}

// The glTF material's radiance with the base colour `colour` and no texture: what a textured
// point whose texel decodes to `colour` must show (kd, ka and the highlight all follow it).
Vec3 untextured_gltf(const Vec3& colour) {
    const TempDir dir;
    write_gltf_quad(dir, Json(), Json::array({colour.x, colour.y, colour.z, 1.0}));
    return quad_scene(dir, "quad.gltf").at(0.5f, 0.5f);
}

TEST(ImageTextureScene, GltfBaseColorTextureShowsTheChecker) {
    const TempDir dir;
    write_checker(dir.file("checker.png"));
    write_gltf_quad(dir, {{"index", 0}});
    const QuadScene s = quad_scene(dir, "quad.gltf");
    EXPECT_TRUE(s.d.warnings.empty());
    const Vec3 a = untextured_gltf(linear(kA)), b = untextured_gltf(linear(kB));
    for (int row = 0; row < kRows; ++row) {
        for (int column = 0; column < kColumns; ++column) {
            const std::string where = "cell " + std::to_string(column) + "," + std::to_string(row);
            expect_near(s.at(cell_x(column), cell_y(row)), cell_colour(column, row) == kA ? a : b,
                        1e-3f, where.c_str());
        }
    }
}

TEST(ImageTextureScene, GltfTextureTransformBeyondTheNumberLimitIsRefused) {
    // A rotation or scale of 1e308 overflows the float transform, an offset of 1e38 the lookups
    // after it (NaN pixels before); 1e18, the scene's number limit, still loads.
    const TempDir dir;
    write_checker(dir.file("checker.png"));
    const auto with = [&](const char* key, const Json& value) {
        write_gltf_quad(
            dir, {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{key, value}}}}}});
        try {
            quad_scene(dir, "quad.gltf");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    for (const auto& [key, value] :
         std::vector<std::pair<const char*, Json>>{{"rotation", 1e308},
                                                   {"scale", Json::array({1e308, 1.0})},
                                                   {"offset", Json::array({1e38, 0.0})}}) {
        const std::string message = with(key, value);
        EXPECT_NE(message.find("quad.gltf: material 'checker' baseColorTexture: "
                               "KHR_texture_transform's offset, rotation and scale must be finite"),
                  std::string::npos)
            << key << ": " << message;
    }
    EXPECT_EQ(with("offset", Json::array({1e18, 0.0})), "accepted");
}

TEST(ImageTextureScene, GltfTextureTransformOffsetRotationScale) {
    const TempDir dir;
    write_checker(dir.file("checker.png"));
    const Vec3 a = untextured_gltf(linear(kA)), b = untextured_gltf(linear(kB));
    // Offset by one column: the top-left cell shows B.
    write_gltf_quad(dir, {{"index", 0},
                          {"extensions", {{"KHR_texture_transform", {{"offset", {1.0 / 3, 0}}}}}}});
    expect_near(quad_scene(dir, "quad.gltf").at(cell_x(0), cell_y(0)), b, 1e-3f, "offset");
    // Rotation by r = π/2 as the extension's sample model checks it (green arrow of
    // TextureTransformTest), (s, t) = (u cos r + v sin r, −u sin r + v cos r): (u, v) =
    // (1/6, 1/4) goes to (1/4, −1/6), repeated to (1/4, 5/6): column 0, row 1 (B). The
    // untransformed lookup and the opposite rotation, (−1/4, 1/6), both read A.
    write_gltf_quad(
        dir, {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"rotation", M_PI / 2}}}}}});
    expect_near(quad_scene(dir, "quad.gltf").at(1.0f / 6.0f, 0.75f), b, 1e-3f, "rotation");
    // Scale 2 in u: u = 1/12 reads s = 1/6 (column 0, A), u = 3/12 reads s = 1/2 (column 1, B).
    write_gltf_quad(
        dir, {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {2.0, 1.0}}}}}}});
    const QuadScene scaled = quad_scene(dir, "quad.gltf");
    expect_near(scaled.at(1.0f / 12.0f, cell_y(0)), a, 1e-3f, "scale, column 0");
    expect_near(scaled.at(3.0f / 12.0f, cell_y(0)), b, 1e-3f, "scale, column 1");
}

TEST(ImageTextureScene, GltfMissingImageIsAWarning) {
    const TempDir dir;
    write_gltf_quad(dir, {{"index", 0}});  // no checker.png beside it
    const QuadScene s = quad_scene(dir, "quad.gltf");
    ASSERT_FALSE(s.d.warnings.empty());
    const std::string& warning = s.d.warnings.back();
    EXPECT_NE(warning.find("checker.png"), std::string::npos) << warning;
    EXPECT_NE(warning.find("material 'checker'"), std::string::npos) << warning;
    expect_near(s.at(0.5f, 0.5f), untextured_gltf(Vec3(1.0f)), 1e-5f, "factor");
}

TEST(ImageTextureScene, JsonImageOnAMeshAndItsColourSpace) {
    const TempDir dir;
    write_checker(dir.file("checker.png"));
    dir.write("plain.obj",
              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
              "f 1/1 2/2 3/3 4/4\n");
    const auto scene = [&](const std::string& kd) {
        QuadScene s;
        s.d = load_json_string(
            R"({"rayo": 1, "ambient_light": 0,
                "materials": {"m": {"kd": )" +
                kd + R"(, "ks": 0}},
                "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1}],
                "objects": [{"type": "mesh", "file": "plain.obj", "material": "m"}]})",
            dir.file("scene.json"), dir.path());
        return s;
    };
    expect_near(scene(R"({"image": "checker.png"})").at(cell_x(0), cell_y(0)), linear(kA), 1e-3f,
                "auto: sRGB");
    expect_near(
        scene(R"({"image": "checker.png", "colorspace": "linear"})").at(cell_x(0), cell_y(0)),
        Vec3(230 / 255.0f, 30 / 255.0f, 30 / 255.0f), 1e-3f, "linear");
    expect_near(
        scene(R"({"image": "checker.png", "factor": [1, 0.5, 0]})").at(cell_x(1), cell_y(0)),
        linear(kB) * Vec3(1.0f, 0.5f, 0.0f), 1e-3f, "factor");
}

TEST(ImageTextureScene, JsonImageOnAnAnalyticShapeUsesItsParameterization) {
    const TempDir dir;
    write_checker(dir.file("checker.png"));
    SceneDescription d = load_json_string(
        R"({"rayo": 1, "ambient_light": 0,
            "camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0], "vfov": 40,
                       "width": 32, "height": 32},
            "render": {"texture_cache_mb": 8},
            "materials": {"m": {"kd": {"image": "checker.png"}, "ks": 0}},
            "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1}],
            "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})",
        dir.file("scene.json"), dir.path());
    const RenderResult r = render_scene(d, 1, false);
    // Both colours appear (within the light's cosine): the sphere's (u, v) addresses the image.
    int reddish = 0, bluish = 0;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const Vec3 c = r.film.rgb(x, y);
            reddish += c.x > 4.0f * c.z;
            bluish += c.z > 4.0f * c.x;
        }
    }
    EXPECT_GT(reddish, 20);
    EXPECT_GT(bluish, 20);
    EXPECT_EQ(r.textures.textures, 1u);
    EXPECT_EQ(r.textures.limit_mb, 8.0f);
    EXPECT_GT(r.textures.memory_used, 0);
    EXPECT_GE(r.textures.memory_peak, r.textures.memory_used);
}

TEST(ImageTextureScene, BadJsonImagesAreRefusedWithTheirPointer) {
    const TempDir dir;
    write_checker(dir.file("checker.png"));
    dir.write("notes.png", "not an image at all");
    dir.write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const auto error = [&](const std::string& material, const std::string& object = "") {
        return json_error_of(
            R"({"rayo": 1, "materials": {"m": )" + material + R"(}, "objects": [)" + object + "]}",
            "s.json", dir.path());
    };
    const auto expect_error = [](const std::string& message, const std::string& start,
                                 const std::string& contains) {
        EXPECT_EQ(message.rfind(start, 0), 0u) << message;
        EXPECT_NE(message.find(contains), std::string::npos) << message;
    };
    expect_error(error(R"({"kd": {"image": "absent.png"}})"), "s.json#/materials/m/kd/image",
                 "absent.png");
    expect_error(error(R"({"kd": {"image": "notes.png"}})"), "s.json#/materials/m/kd/image",
                 "cannot be read");
    expect_error(error(R"({"kd": {"image": 3}})"), "s.json#/materials/m/kd/image",
                 "expected the path of an image file");
    expect_error(error(R"({"kd": {"file": "checker.png"}})"), "s.json#/materials/m/kd", "image");
    expect_error(error(R"({"kd": {"image": "checker.png", "wrap": "tile"}})"),
                 "s.json#/materials/m/kd/wrap", "tile");
    expect_error(error(R"({"emission": {"image": "checker.png", "scale": [1, 2, 3]}})"),
                 "s.json#/materials/m/emission/scale", "[u, v]");
    expect_error(error(R"({"kd": {"image": "checker.png"}})",
                       R"({"type": "mesh", "file": "plain.obj", "material": "m"})"),
                 "s.json#/objects/0/material", "no texture coordinates");
    EXPECT_EQ(error(R"({"kd": {"image": "checker.png"}})"), "no error");
}

}  // namespace
}  // namespace rayo
