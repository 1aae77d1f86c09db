// Normal maps, bump maps and cutouts end to end (docs/models.md, "Normal and bump maps",
// "Cutouts"): a unit quad facing +z with images written by the test (OpenImageIO ImageOutput),
// loaded through OBJ+MTL (norm, map_bump -bm, map_d) and glTF (normalTexture with and without
// TANGENT, alphaMode MASK/BLEND), shaded where the images' cells are known; holes let camera
// rays and shadow rays through, on the single-ray and the stream paths alike; bad input gets
// the loaders' errors and warnings.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "apps/scene/json_loader.h"
#include "apps/scene/mesh_loader.h"
#include "apps/scene/renderer.h"
#include "core/accel.h"
#include "core/error.h"
#include "shading/cutouts.h"
#include "shading/integrators/whitted.h"
#include "tests/scene/gltf_test_writer.h"
#include "tests/scene/scene_test_files.h"

namespace rayo {
namespace {

using Json = nlohmann::json;
using rayo_test::TempDir;

// An image of `channels` 8-bit channels, texel (x, y) (y = 0 the top row) = texel(x, y, c).
void write_image(const std::string& path, int w, int h, int channels,
                 const std::function<unsigned char(int, int, int)>& texel) {
    std::vector<unsigned char> pixels(static_cast<size_t>(w * h * channels));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            for (int c = 0; c < channels; ++c) {
                pixels[static_cast<size_t>((y * w + x) * channels + c)] = texel(x, y, c);
            }
        }
    }
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(path, OIIO::ImageSpec(w, h, channels, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
    out->close();
}

// The normal map: 2 × 2 cells of 8 texels, each tilting the normal one way in tangent space
// (+Y the image's up): top-left +x, top-right −x, bottom-left +y, bottom-right −y.
constexpr int kCell = 8;
const unsigned char kTilts[4][3] = {
    {217, 128, 221}, {38, 128, 221}, {128, 217, 221}, {128, 38, 221}};
void write_normal_map(const std::string& path) {
    write_image(path, 2 * kCell, 2 * kCell, 3,
                [](int x, int y, int c) { return kTilts[(y / kCell) * 2 + x / kCell][c]; });
}
// The world normal a cell means on the quad (tangent +x, bitangent +y, normal +z), written out
// here from the bytes: normalize(2·byte/255 − 1).
Vec3 cell_normal(int cell) {
    const Vec3 m(2.0f * kTilts[cell][0] / 255.0f - 1.0f, 2.0f * kTilts[cell][1] / 255.0f - 1.0f,
                 2.0f * kTilts[cell][2] / 255.0f - 1.0f);
    return glm::normalize(m);
}
// World (x, y) at the centre of a cell: the quads put the image's top at y = 1.
float cell_x(int cell) {
    return cell % 2 == 0 ? 0.25f : 0.75f;
}
float cell_y(int cell) {
    return cell < 2 ? 0.75f : 0.25f;
}

// A loaded scene traced as the renderer traces it: image textures, the cutouts' filters.
struct MapScene {
    SceneDescription d;
    std::unique_ptr<ImageTextures> images;
    std::unique_ptr<MaterialCutouts> cutouts;
    std::unique_ptr<Accel> accel;
    std::unique_ptr<WhittedIntegrator> integrator;

    Ray ray_at(float x, float y) const {
        Ray ray;
        ray.origin = Vec3(x, y, 5.0f);
        ray.direction = Vec3(0.0f, 0.0f, -1.0f);
        return ray;
    }
    Vec3 at(float x, float y) const {
        RayCounters counters;
        return integrator->radiance(ray_at(x, y), counters);
    }
};

// `objects`: mesh files; the light: directional, travelling along `light`, intensity 1.
std::unique_ptr<MapScene> map_scene(const TempDir& dir, const std::vector<std::string>& objects,
                                    const Vec3& light) {
    auto s = std::make_unique<MapScene>();
    Json scene = {
        {"rayo", 1},
        {"ambient_light", 0},
        {"lights",
         {{{"type", "directional"}, {"direction", {light.x, light.y, light.z}}, {"intensity", 1}}}},
        {"objects", Json::array()}};
    for (const std::string& file : objects) {
        scene["objects"].push_back({{"type", "mesh"}, {"file", file}});
    }
    s->d = load_json_string(scene.dump(), dir.file("scene.json"), dir.path());
    s->images = std::make_unique<ImageTextures>(s->d.shading.materials, kDefaultTextureCacheMB);
    s->cutouts = std::make_unique<MaterialCutouts>(s->d.shading.materials, s->images.get());
    AccelOptions options;
    if (s->cutouts->any()) options.cutouts = s->cutouts.get();
    s->accel = std::make_unique<Accel>(s->d.scene, options);
    s->integrator = std::make_unique<WhittedIntegrator>(
        *s->accel, s->d.shading, s->d.settings.whitted(), nullptr, s->images.get());
    return s;
}

const char* const kQuadObj =
    "mtllib quad.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
    "usemtl quad\nf 1/1/1 2/2/2 3/3/3 4/4/4\n";

// Light travelling along −l hits a Lambertian white quad (Ks 0, Ka 0) with normal n: n·l.
float lambert(const Vec3& n, const Vec3& travel) {
    return glm::max(0.0f, glm::dot(n, -glm::normalize(travel)));
}

TEST(SurfaceMapsScene, ObjNormMapTiltsTheShadingNormalAsTheTexelsSay) {
    const TempDir dir;
    write_normal_map(dir.file("normal.png"));
    dir.write("quad.obj", kQuadObj);
    dir.write("quad.mtl", "newmtl quad\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nnorm normal.png\n");
    for (const Vec3& light : {Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(0, -1, -1), Vec3(0, 1, -1)}) {
        const auto s = map_scene(dir, {"quad.obj"}, light);
        EXPECT_TRUE(s->d.warnings.empty());
        for (int cell = 0; cell < 4; ++cell) {
            const float expected = lambert(cell_normal(cell), light);
            EXPECT_NEAR(s->at(cell_x(cell), cell_y(cell)).x, expected, 2e-3f)
                << "cell " << cell << ", light " << light.x << " " << light.y;
        }
    }
    // Lit from +x, the cell tilted toward +x is brighter than a flat quad and the −x one darker.
    const auto s = map_scene(dir, {"quad.obj"}, Vec3(-1, 0, -1));
    const float flat = lambert(Vec3(0, 0, 1), Vec3(-1, 0, -1));
    EXPECT_GT(s->at(cell_x(0), cell_y(0)).x, flat + 0.2f);
    EXPECT_LT(s->at(cell_x(1), cell_y(1)).x, flat - 0.2f);
}

// A height ramp along the image's x (columns; `along_x`) or down its rows, byte = 16·index.
void write_ramp(const std::string& path, bool along_x) {
    write_image(path, 16, 16, 1, [along_x](int x, int y, int) {
        return static_cast<unsigned char>(16 * (along_x ? x : y));
    });
}

TEST(SurfaceMapsScene, ObjBumpMapTiltsAgainstTheHeightGradient) {
    const TempDir dir;
    write_ramp(dir.file("ramp_x.png"), true);
    write_ramp(dir.file("ramp_y.png"), false);
    dir.write("quad.obj", kQuadObj);
    // Height along u: F = 0.5 × (16/255 per texel, 16 texels per unit) = 0.5·256/255 per unit
    // of u and of x: the surface rises toward +x, so its normal is normalize(−F_x, 0, 1).
    dir.write("quad.mtl",
              "newmtl quad\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nmap_bump -bm 0.5 ramp_x.png\n");
    const float slope = 0.5f * 256.0f / 255.0f;
    const Vec3 tilted = glm::normalize(Vec3(-slope, 0.0f, 1.0f));
    for (const Vec3& light : {Vec3(-1, 0, -1), Vec3(1, 0, -1)}) {
        const auto s = map_scene(dir, {"quad.obj"}, light);
        EXPECT_TRUE(s->d.warnings.empty());
        EXPECT_NEAR(s->at(0.5f, 0.5f).x, lambert(tilted, light), 2e-3f) << light.x;
    }
    // Lit from +x the rising surface is darker than flat, from −x brighter.
    const float flat = lambert(Vec3(0, 0, 1), Vec3(-1, 0, -1));
    EXPECT_LT(map_scene(dir, {"quad.obj"}, Vec3(-1, 0, -1))->at(0.5f, 0.5f).x, flat - 0.2f);
    EXPECT_GT(map_scene(dir, {"quad.obj"}, Vec3(1, 0, -1))->at(0.5f, 0.5f).x, flat + 0.2f);
    // Heights growing down the image grow toward −y on the quad (its top at y = 1): the normal
    // tilts toward +y.
    dir.write("quad.mtl", "newmtl quad\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nbump -bm 0.5 ramp_y.png\n");
    const Vec3 up = glm::normalize(Vec3(0.0f, slope, 1.0f));
    const Vec3 from_up(0, -1, -1);
    EXPECT_NEAR(map_scene(dir, {"quad.obj"}, from_up)->at(0.5f, 0.5f).x, lambert(up, from_up),
                2e-3f);
}

// A glTF quad (the image's top at y = 1, normals +z) with `material`; `tangents` (one per
// corner, xyzw) adds a TANGENT attribute. Images: "normal.png", "alpha.png".
std::string write_gltf_quad(const TempDir& dir, const Json& material,
                            const std::vector<float>& tangents = {},
                            const std::string& name = "quad.gltf") {
    rayo_test::GltfTestWriter g;
    Json attributes = {{"POSITION", g.positions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0})},
                       {"NORMAL", g.accessor({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")},
                       {"TEXCOORD_0", g.accessor({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2")}};
    const int index = g.indices({0, 1, 2, 0, 2, 3});
    if (!tangents.empty()) attributes["TANGENT"] = g.accessor(tangents, "VEC4");
    g.node({{"mesh", g.mesh({{"attributes", attributes},
                             {"indices", index},
                             {"material", g.push("materials", material)}})}});
    g.doc()["textures"] = {{{"source", 0}}, {{"source", 1}}};
    g.doc()["images"] = {{{"uri", "normal.png"}}, {{"uri", "alpha.png"}}};
    return g.write_embedded(dir, name);
}

Json gltf_material(const Json& extra = Json::object()) {
    Json m = {{"name", "quad"},
              {"pbrMetallicRoughness",
               {{"baseColorFactor", {1.0, 1.0, 1.0, 1.0}},
                {"metallicFactor", 0.0},
                {"roughnessFactor", 1.0}}}};
    m.update(extra);
    return m;
}

TEST(SurfaceMapsScene, GltfNormalTextureWithComputedAndGivenTangents) {
    const TempDir dir;
    write_normal_map(dir.file("normal.png"));
    const Vec3 from_x(-1, 0, -1), from_y(0, -1, -1);
    write_gltf_quad(dir, gltf_material());
    const float flat = map_scene(dir, {"quad.gltf"}, from_x)->at(0.5f, 0.5f).x;
    // No TANGENT: computed (Lengyel). The cells tilt toward ±x and ±y as the texels say.
    write_gltf_quad(dir, gltf_material({{"normalTexture", {{"index", 0}}}}));
    const auto computed_x = map_scene(dir, {"quad.gltf"}, from_x);
    const auto computed_y = map_scene(dir, {"quad.gltf"}, from_y);
    EXPECT_TRUE(computed_x->d.warnings.empty());
    EXPECT_GT(computed_x->at(cell_x(0), cell_y(0)).x, flat + 0.2f);
    EXPECT_LT(computed_x->at(cell_x(1), cell_y(1)).x, flat - 0.2f);
    EXPECT_GT(computed_y->at(cell_x(2), cell_y(2)).x, flat + 0.2f);
    EXPECT_LT(computed_y->at(cell_x(3), cell_y(3)).x, flat - 0.2f);
    // The same with the tangents given as the quad's own, +x with w = +1.
    const std::vector<float> given = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
    write_gltf_quad(dir, gltf_material({{"normalTexture", {{"index", 0}}}}), given);
    for (const Vec3& light : {from_x, from_y}) {
        const auto with_tangents = map_scene(dir, {"quad.gltf"}, light);
        const auto& without = light == from_x ? computed_x : computed_y;
        for (int cell = 0; cell < 4; ++cell) {
            EXPECT_NEAR(with_tangents->at(cell_x(cell), cell_y(cell)).x,
                        without->at(cell_x(cell), cell_y(cell)).x, 1e-5f)
                << cell;
        }
    }
    // Given tangents are used: −x mirrors the x tilts; scale 0 flattens the map.
    const std::vector<float> reversed = {-1, 0, 0, 1, -1, 0, 0, 1, -1, 0, 0, 1, -1, 0, 0, 1};
    write_gltf_quad(dir, gltf_material({{"normalTexture", {{"index", 0}}}}), reversed);
    const auto mirrored = map_scene(dir, {"quad.gltf"}, from_x);
    EXPECT_NEAR(mirrored->at(cell_x(0), cell_y(0)).x, computed_x->at(cell_x(1), cell_y(1)).x,
                1e-5f);
    write_gltf_quad(dir, gltf_material({{"normalTexture", {{"index", 0}, {"scale", 0.0}}}}));
    EXPECT_NEAR(map_scene(dir, {"quad.gltf"}, from_x)->at(cell_x(0), cell_y(0)).x,
                map_scene(dir, {"quad.gltf"}, from_x)->at(cell_x(1), cell_y(1)).x, 1e-3f);
}

TEST(SurfaceMapsScene, ComputedTangentsAgreeWithTheQuadsOwn) {
    const TempDir dir;
    write_normal_map(dir.file("normal.png"));
    write_gltf_quad(dir, gltf_material({{"normalTexture", {{"index", 0}}}}));
    std::vector<Material> materials;
    MeshImportOptions options;
    options.where = "test";
    const ImportedMesh imported = import_mesh_file(dir.file("quad.gltf"), materials, options);
    ASSERT_EQ(imported.mesh.tangents.size(), 4u);
    for (const glm::vec4& t : imported.mesh.tangents) {
        EXPECT_NEAR(t.x, 1.0f, 1e-6f);
        EXPECT_NEAR(t.y, 0.0f, 1e-6f);
        EXPECT_NEAR(t.z, 0.0f, 1e-6f);
        EXPECT_EQ(t.w, 1.0f);
    }
    // Without a normal-mapped material, none are made.
    write_gltf_quad(dir, gltf_material());
    materials.clear();
    EXPECT_TRUE(import_mesh_file(dir.file("quad.gltf"), materials, options).mesh.tangents.empty());
}

// Behind the quads: an opaque blue quad at z = −1 from (−1, −1) to (2, 2), facing +z.
void write_background(const TempDir& dir) {
    dir.write("back.obj",
              "mtllib back.mtl\nv -1 -1 -1\nv 2 -1 -1\nv 2 2 -1\nv -1 2 -1\nusemtl back\n"
              "f 1 2 3 4\n");
    dir.write("back.mtl", "newmtl back\nKa 0 0 0\nKd 0 0 1\nKs 0 0 0\n");
}

// The checks of a cutout quad whose left half (x < 0.5) is a hole, over the background, lit
// along (−1, 0, −1): camera rays through the hole see the background and not through the
// rest; the background at x = −0.75 sees the light through the hole, at x = −0.25 the opaque
// half shadows it. The stream path gives the same values bit for bit.
void expect_left_half_cut(const MapScene& s) {
    const float lit = lambert(Vec3(0, 0, 1), Vec3(-1, 0, -1));
    EXPECT_EQ(s.accel->cutout_mesh_count(), 1u);
    const Vec3 hole = s.at(0.25f, 0.5f), opaque = s.at(0.75f, 0.5f);
    EXPECT_NEAR(hole.z, lit, 1e-4f);  // the background, lit through the hole
    EXPECT_NEAR(hole.x, 0.0f, 1e-6f);
    EXPECT_GT(opaque.x, 0.1f);  // the quad (red or white), not the blue background
    EXPECT_NEAR(s.at(-0.75f, 0.5f).z, lit, 1e-4f);  // its light came through the hole
    EXPECT_EQ(s.at(-0.25f, 0.5f), Vec3(0.0f));      // shadowed by the opaque half
    const std::vector<Ray> rays = {s.ray_at(0.25f, 0.5f), s.ray_at(0.75f, 0.5f),
                                   s.ray_at(-0.75f, 0.5f), s.ray_at(-0.25f, 0.5f)};
    std::vector<Vec3> streamed(rays.size());
    RayCounters counters;
    s.integrator->radiance_coherent(rays.data(), static_cast<int>(rays.size()), streamed.data(),
                                    counters);
    for (size_t i = 0; i < rays.size(); ++i) {
        EXPECT_EQ(streamed[i], s.integrator->radiance(rays[i], counters)) << i;
    }
}

TEST(SurfaceMapsScene, ObjMapDCutsHolesForCameraAndShadowRays) {
    const TempDir dir;
    write_background(dir);
    // Grey, no alpha channel: its luminance is the coverage (black left half, white right).
    write_image(dir.file("cover.png"), 16, 16, 1,
                [](int x, int, int) { return static_cast<unsigned char>(x < 8 ? 0 : 255); });
    dir.write("quad.obj", kQuadObj);
    dir.write("quad.mtl", "newmtl quad\nKa 0 0 0\nKd 1 0 0\nKs 0 0 0\nmap_d cover.png\n");
    const auto s = map_scene(dir, {"quad.obj", "back.obj"}, Vec3(-1, 0, -1));
    EXPECT_TRUE(s->d.warnings.empty());
    expect_left_half_cut(*s);
    // An image with alpha: its alpha decides, not its colour (white everywhere).
    write_image(dir.file("cover.png"), 16, 16, 4, [](int x, int, int c) {
        return static_cast<unsigned char>(c < 3 || x >= 8 ? 255 : 0);
    });
    expect_left_half_cut(*map_scene(dir, {"quad.obj", "back.obj"}, Vec3(-1, 0, -1)));
}

TEST(SurfaceMapsScene, ObjMissingMapDIsAWarningAndTheSurfaceStaysWhole) {
    const TempDir dir;
    write_background(dir);
    dir.write("quad.obj", kQuadObj);
    dir.write("quad.mtl", "newmtl quad\nKa 0 0 0\nKd 1 0 0\nKs 0 0 0\nmap_d gone.png\n");
    const auto s = map_scene(dir, {"quad.obj", "back.obj"}, Vec3(-1, 0, -1));
    ASSERT_EQ(s->d.warnings.size(), 1u);
    EXPECT_NE(s->d.warnings[0].find("gone.png"), std::string::npos) << s->d.warnings[0];
    EXPECT_NE(s->d.warnings[0].find("material 'quad' map_d"), std::string::npos)
        << s->d.warnings[0];
    EXPECT_EQ(s->accel->cutout_mesh_count(), 0u);
    EXPECT_GT(s->at(0.25f, 0.5f).x, 0.1f);  // the quad, not the background
}

// White RGBA, alpha 0 on the left half (x < 8 of 16) and 255 on the right.
void write_alpha_png(const TempDir& dir) {
    write_image(dir.file("alpha.png"), 16, 16, 4, [](int x, int, int c) {
        return static_cast<unsigned char>(c < 3 || x >= 8 ? 255 : 0);
    });
}

TEST(SurfaceMapsScene, GltfAlphaMaskCutsHolesForCameraAndShadowRays) {
    const TempDir dir;
    write_background(dir);
    write_alpha_png(dir);
    Json mask = gltf_material({{"alphaMode", "MASK"}});
    mask["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 1}};
    write_gltf_quad(dir, mask);
    const auto s = map_scene(dir, {"quad.gltf", "back.obj"}, Vec3(-1, 0, -1));
    EXPECT_TRUE(s->d.warnings.empty());
    expect_left_half_cut(*s);
    // Opaque (the default alphaMode): the same texture makes no hole.
    Json opaque = gltf_material();
    opaque["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 1}};
    write_gltf_quad(dir, opaque);
    const auto whole = map_scene(dir, {"quad.gltf", "back.obj"}, Vec3(-1, 0, -1));
    EXPECT_EQ(whole->accel->cutout_mesh_count(), 0u);
    EXPECT_GT(whole->at(0.25f, 0.5f).x, 0.1f);
}

TEST(SurfaceMapsScene, GltfMaskFactorAlphaAndCutoffAndBlend) {
    const TempDir dir;
    write_background(dir);
    // No texture: alpha is baseColorFactor's, 0.4: below the default cutoff 0.5 the whole quad
    // is a hole; with alphaCutoff 0.3 it is whole.
    Json faint = gltf_material({{"alphaMode", "MASK"}});
    faint["pbrMetallicRoughness"]["baseColorFactor"] = {1.0, 1.0, 1.0, 0.4};
    write_gltf_quad(dir, faint);
    const Vec3 from_x(-1, 0, -1);
    const float background = lambert(Vec3(0, 0, 1), from_x);
    EXPECT_NEAR(map_scene(dir, {"quad.gltf", "back.obj"}, from_x)->at(0.75f, 0.5f).z, background,
                1e-4f);
    faint["alphaCutoff"] = 0.3;
    write_gltf_quad(dir, faint);
    EXPECT_GT(map_scene(dir, {"quad.gltf", "back.obj"}, from_x)->at(0.75f, 0.5f).x, 0.1f);
    // BLEND: read as MASK at 0.5, with a warning naming the material.
    write_alpha_png(dir);
    Json blend = gltf_material({{"alphaMode", "BLEND"}});
    blend["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 1}};
    write_gltf_quad(dir, blend);
    const auto s = map_scene(dir, {"quad.gltf", "back.obj"}, from_x);
    ASSERT_EQ(s->d.warnings.size(), 1u);
    EXPECT_NE(s->d.warnings[0].find("material 'quad': alphaMode BLEND"), std::string::npos)
        << s->d.warnings[0];
    expect_left_half_cut(*s);
}

std::string load_error(const TempDir& dir) {
    try {
        map_scene(dir, {"quad.gltf"}, Vec3(0, 0, -1));
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(SurfaceMapsScene, BadNormalTextureAndAlphaInputAreRefusedAsForOtherTextures) {
    const TempDir dir;
    write_normal_map(dir.file("normal.png"));
    // A normalTexture index out of range: the error the base colour texture gets.
    write_gltf_quad(dir, gltf_material({{"normalTexture", {{"index", 7}}}}));
    EXPECT_NE(load_error(dir).find("material 'quad' normalTexture: texture 7 does not exist"),
              std::string::npos)
        << load_error(dir);
    write_gltf_quad(dir, gltf_material({{"alphaMode", "CUTOUT"}}));
    EXPECT_NE(load_error(dir).find("alphaMode must be OPAQUE, MASK or BLEND, got 'CUTOUT'"),
              std::string::npos)
        << load_error(dir);
    write_gltf_quad(dir, gltf_material({{"alphaMode", "MASK"}, {"alphaCutoff", -0.5}}));
    EXPECT_NE(load_error(dir).find("alphaCutoff must be finite and >= 0"), std::string::npos)
        << load_error(dir);
    // A missing normal map image: a warning, the quad shaded flat.
    std::remove(dir.file("normal.png").c_str());
    write_gltf_quad(dir, gltf_material({{"normalTexture", {{"index", 0}}}}));
    const auto s = map_scene(dir, {"quad.gltf"}, Vec3(-1, 0, -1));
    ASSERT_EQ(s->d.warnings.size(), 1u);
    EXPECT_NE(s->d.warnings[0].find("normalTexture: image"), std::string::npos) << s->d.warnings[0];
    EXPECT_NEAR(s->at(0.25f, 0.75f).x, s->at(0.75f, 0.75f).x, 1e-6f);
}

}  // namespace
}  // namespace rayo
