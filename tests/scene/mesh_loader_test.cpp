// Tests of mesh import (apps/scene/mesh_loader.h): OBJ with MTL materials mapped onto Phong, glTF
// as base64-embedded .gltf, external .bin and .glb (written by the tests), node transforms, index
// types, degenerate triangles, and the errors for missing and malformed files.
#include "apps/scene/mesh_loader.h"

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <gtest/gtest.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/error.h"
#include "tests/scene/gltf_test_writer.h"
#include "tests/scene/scene_test_files.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using Json = nlohmann::json;
using rayo_test::expect_vec3;

using rayo_test::TempDir;

template <typename F>
InputError expect_input_error(F&& f) {
    try {
        f();
    } catch (const InputError& error) {
        return error;
    }
    ADD_FAILURE() << "no InputError";
    return InputError("", "");
}

// ---- OBJ ------------------------------------------------------------------------------------

const char* const kMtl =
    "newmtl plastic\nKa 0.1 0.2 0.3\nKd 0.4 0.5 0.6\nKs 0.7 0.8 0.9\nNs 50\nillum 2\n"
    "newmtl mirror\nKd 0.1 0.1 0.1\nKs 0.9 0.8 0.7\nNs 300\nillum 3\n"
    "newmtl glass\nKd 0 0 0\nKs 0.5 0.5 0.5\nd 0.25\nNi 1.45\nillum 2\n";

const char* const kQuadsObj =
    "mtllib mats.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\n"
    "vn 0 0 2\n"
    "usemtl plastic\nf 1//1 2//1 3//1 4//1\n"  // a quad: two triangles
    "usemtl mirror\nf 1 2 6\n"
    "usemtl glass\nf 2 3 6\n";

TEST(MeshLoaderObj, MtlMaterialsMappedOntoPhong) {
    TempDir dir;
    dir.write("mats.mtl", kMtl);
    const std::string path = dir.write("quads.obj", kQuadsObj);
    std::vector<Material> materials(2);  // the loader appends after existing ones
    MeshImportStats stats;
    const TriangleMesh mesh = load_obj(path, materials, "here", &stats);
    EXPECT_EQ(stats.file_materials, 3u);
    EXPECT_EQ(stats.degenerate_triangles, 0u);
    ASSERT_EQ(materials.size(), 5u);
    const Material& plastic = materials[2];
    EXPECT_EQ(plastic.name, "plastic");
    expect_vec3(plastic.ka, 0.1f, 0.2f, 0.3f);
    expect_vec3(plastic.kd, 0.4f, 0.5f, 0.6f);
    expect_vec3(plastic.ks, 0.7f, 0.8f, 0.9f);
    EXPECT_EQ(plastic.shininess, 50.0f);
    expect_vec3(plastic.reflect, 0, 0, 0);  // illum 2: no mirror
    expect_vec3(plastic.transmit, 0, 0, 0);
    const Material& mirror = materials[3];
    expect_vec3(mirror.reflect, 0.9f, 0.8f, 0.7f);  // illum 3: reflect = Ks
    EXPECT_EQ(mirror.shininess, 300.0f);
    const Material& glass = materials[4];
    expect_vec3(glass.transmit, 0.75f, 0.75f, 0.75f);  // 1 − d
    EXPECT_FLOAT_EQ(glass.ior, 1.45f);
    // MTL has no sidedness: every OBJ material is two-sided (docs/radiosity.md).
    for (size_t i = 2; i < 5; ++i) EXPECT_TRUE(materials[i].double_sided) << i;

    ASSERT_EQ(mesh.triangle_count(), 4u);
    EXPECT_EQ(mesh.materials[0], 2u);
    EXPECT_EQ(mesh.materials[1], 2u);
    EXPECT_EQ(mesh.materials[2], 3u);
    EXPECT_EQ(mesh.materials[3], 4u);
    // The quad's corners carry the (normalized) file normal; the other faces have none (zero).
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    expect_vec3(mesh.normals[mesh.triangles[0][0]], 0, 0, 1);
    expect_vec3(mesh.normals[mesh.triangles[2][2]], 0, 0, 0);
    expect_vec3(mesh.positions[mesh.triangles[2][2]], 1, 0, 1);
}

TEST(MeshLoaderObj, VertexColoursExtension) {
    TempDir dir;
    const std::string path =
        dir.write("c.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n");
    std::vector<Material> materials;
    const TriangleMesh mesh = load_obj(path, materials, "here");
    ASSERT_EQ(mesh.colors.size(), 3u);
    expect_vec3(mesh.colors[1], 0, 1, 0);
    // Without colours on every vertex there are none; a negative colour is refused.
    const std::string plain = dir.write("p.obj", "v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_TRUE(load_obj(plain, materials, "here").colors.empty());
    const std::string bad =
        dir.write("b.obj", "v 0 0 0 1 -1 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n");
    const InputError error = expect_input_error([&] { load_obj(bad, materials, "here"); });
    EXPECT_NE(error.message().find("vertex 1 colour"), std::string::npos) << error.message();
}

TEST(MeshLoaderObj, FacesWithoutMaterialUseDefault) {
    TempDir dir;
    const std::string path = dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    std::vector<Material> materials;
    const TriangleMesh mesh = load_obj(path, materials, "here");
    ASSERT_EQ(materials.size(), 1u);
    EXPECT_EQ(materials[0].name, "default");
    EXPECT_EQ(mesh.materials.at(0), 0u);
    EXPECT_TRUE(mesh.normals.empty());

    std::vector<Material> with_default(3);
    with_default[1].name = "default";
    const TriangleMesh again = load_obj(path, with_default, "here");
    EXPECT_EQ(with_default.size(), 3u);  // found, not appended
    EXPECT_EQ(again.materials.at(0), 1u);
}

TEST(MeshLoaderObj, DegenerateTrianglesDroppedAndCounted) {
    TempDir dir;
    const std::string path =
        dir.write("deg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nf 1 1 3\n");
    std::vector<Material> materials;
    MeshImportStats stats;
    const TriangleMesh mesh = load_obj(path, materials, "here", &stats);
    EXPECT_EQ(mesh.triangle_count(), 1u);
    EXPECT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(stats.degenerate_triangles, 2u);
}

TEST(MeshLoaderObj, MissingFileNamesWhereAndPath) {
    std::vector<Material> materials;
    const InputError error = expect_input_error(
        [&] { load_obj("/nonexistent/rayo/x.obj", materials, "scene.json#/objects/2/file"); });
    EXPECT_EQ(error.where(), "scene.json#/objects/2/file");
    EXPECT_NE(error.message().find("/nonexistent/rayo/x.obj"), std::string::npos);
}

TEST(MeshLoaderObj, MalformedFaceGivesFileAndLine) {
    TempDir dir;
    const std::string path = dir.write("bad.obj", "# header\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    std::vector<Material> materials;
    const InputError error = expect_input_error([&] { load_obj(path, materials, "here"); });
    EXPECT_EQ(error.where(), path + ":5");
    EXPECT_NE(error.message().find("out of bounds"), std::string::npos) << error.message();
}

TEST(MeshLoaderObj, ZeroFaceIndexGivesFileAndLine) {
    TempDir dir;
    const std::string path = dir.write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
    std::vector<Material> materials;
    const InputError error = expect_input_error([&] { load_obj(path, materials, "here"); });
    EXPECT_EQ(error.where(), path + ":4");
}

TEST(MeshLoaderObj, MissingMaterialLibraryIsAWarningWithTheDefaultMaterial) {
    TempDir dir;
    const std::string path =
        dir.write("nomtl.obj", "mtllib gone.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    std::vector<Material> materials;
    MeshImportStats stats;
    const TriangleMesh mesh = load_obj(path, materials, "here", &stats);
    ASSERT_EQ(mesh.triangle_count(), 1u);
    EXPECT_EQ(materials[mesh.materials[0]].name, "default");
    ASSERT_EQ(stats.warnings.size(), 1u);
    EXPECT_EQ(stats.warnings[0].rfind(path + ": material library 'gone.mtl' not found", 0), 0u)
        << stats.warnings[0];
    EXPECT_EQ(stats.warnings[0].find("Use default material"), std::string::npos);
}

// How many times `f` opens the file at `path`, counted with inotify (Linux): IN_OPEN events on
// the file. Closes are watched too, so that two successive opens are two events (inotify merges
// identical consecutive events).
template <typename F>
int opens_of(const std::string& path, F&& f) {
    const int fd = inotify_init1(IN_NONBLOCK);
    EXPECT_GE(fd, 0);
    EXPECT_GE(inotify_add_watch(fd, path.c_str(), IN_OPEN | IN_CLOSE), 0);
    f();
    int opens = 0;
    alignas(inotify_event) char buffer[4096];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) {
        for (ssize_t at = 0; at < n;) {
            const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
            opens += (event->mask & IN_OPEN) != 0;
            at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
        }
    }
    ::close(fd);
    return opens;
}

// load_obj reads the OBJ once: its pre-checks, tinyobjloader and the search for a bad face's
// line all parse the same text (they opened the file up to four times).
TEST(MeshLoaderObj, OpensTheFileOnce) {
    TempDir dir;
    dir.write("mats.mtl", kMtl);
    const std::string path = dir.write("quads.obj", kQuadsObj);
    std::vector<Material> materials;
    EXPECT_EQ(opens_of(path, [&] { load_obj(path, materials, "here"); }), 1);
    const std::string bad = dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    EXPECT_EQ(opens_of(bad, [&] { expect_input_error([&] { load_obj(bad, materials, "here"); }); }),
              1);
}

// The material library is looked up next to the OBJ, also for a path without a directory.
TEST(MeshLoaderObj, MaterialLibraryNextToAnObjInTheWorkingDirectory) {
    TempDir dir;
    dir.write("mats.mtl", kMtl);
    dir.write("quads.obj", kQuadsObj);
    const std::filesystem::path previous = std::filesystem::current_path();
    std::filesystem::current_path(dir.path());
    std::vector<Material> materials;
    MeshImportStats stats;
    EXPECT_NO_THROW(load_obj("quads.obj", materials, "here", &stats));
    std::filesystem::current_path(previous);
    EXPECT_EQ(stats.file_materials, 3u);
}

TEST(MeshLoaderObj, NoTrianglesIsAnError) {
    TempDir dir;
    const std::string path = dir.write("points.obj", "v 0 0 0\nv 1 0 0\n");
    std::vector<Material> materials;
    const InputError error = expect_input_error([&] { load_obj(path, materials, "where"); });
    EXPECT_EQ(error.where(), "where");
    EXPECT_NE(error.message().find("no (non-degenerate) triangles"), std::string::npos);
}

// ---- glTF -----------------------------------------------------------------------------------

using GltfAsset = rayo_test::GltfTestWriter;

// A glTF document with one mesh of one primitive: a unit right triangle in z = 0 plus a second
// triangle (1,0,0),(1,1,0),(0,1,0), with +z normals and `index_type` indices; node 0 instances
// it.
GltfAsset make_gltf(int index_type) {
    GltfAsset a;
    const int position = a.positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
    const int normal = a.accessor({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3");
    const int index = a.indices({0, 1, 2, 1, 3, 2}, index_type);
    const int material = a.push("materials", {{"name", "metal"},
                                              {"pbrMetallicRoughness",
                                               {{"baseColorFactor", {0.5, 0.25, 1.0, 1.0}},
                                                {"metallicFactor", 0.5},
                                                {"roughnessFactor", 0.5}}}});
    a.node({{"mesh", a.mesh({{"attributes", {{"POSITION", position}, {"NORMAL", normal}}},
                             {"indices", index},
                             {"material", material}})}});
    return a;
}

TEST(MeshLoaderGltf, EmbeddedBufferWithPbrMaterial) {
    TempDir dir;
    const std::string path = make_gltf(5123).write_embedded(dir, "tri.gltf");
    std::vector<Material> materials(1);
    MeshImportStats stats;
    const TriangleMesh mesh = load_gltf(path, materials, "here", &stats);
    ASSERT_EQ(mesh.triangle_count(), 2u);
    ASSERT_EQ(mesh.positions.size(), 4u);
    expect_vec3(mesh.positions[3], 1, 1, 0);
    EXPECT_EQ(mesh.triangles[1][0], 1u);
    EXPECT_EQ(mesh.triangles[1][1], 3u);
    EXPECT_EQ(mesh.triangles[1][2], 2u);
    ASSERT_EQ(mesh.normals.size(), 4u);
    expect_vec3(mesh.normals[2], 0, 0, 1);
    EXPECT_EQ(mesh.materials[0], 1u);
    EXPECT_EQ(stats.file_materials, 1u);
    ASSERT_EQ(materials.size(), 2u);
    const Material& m = materials[1];
    EXPECT_EQ(m.name, "metal");
    // metallic 0.5, roughness 0.5: F0 = mix(0.04, base, 0.5), kd = 0.5·base, reflect = F0/4.
    expect_vec3(m.kd, 0.25f, 0.125f, 0.5f);
    expect_vec3(m.ka, 0.05f, 0.025f, 0.1f);
    expect_vec3(m.ks, 0.27f, 0.145f, 0.52f);
    expect_vec3(m.reflect, 0.0675f, 0.03625f, 0.13f);
    EXPECT_FLOAT_EQ(m.shininess, 30.0f);  // 2/0.5⁴ − 2
    expect_vec3(m.emission, 0, 0, 0);
}

TEST(MeshLoaderGltf, RoughnessExtremesClampShininess) {
    for (const auto& [roughness, expected] :
         std::vector<std::pair<double, float>>{{0.0, 10000.0f}, {1.0, 1.0f}, {0.05, 10000.0f}}) {
        TempDir dir;
        GltfAsset a = make_gltf(5123);
        a.doc()["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = roughness;
        const std::string path = a.write_embedded(dir, "r.gltf");
        std::vector<Material> materials;
        load_gltf(path, materials, "here");
        EXPECT_FLOAT_EQ(materials.at(0).shininess, expected) << "roughness " << roughness;
    }
}

TEST(MeshLoaderGltf, MetalsDoNotDiffuseDielectricsKeepTheirColourRoughMirrorsFade) {
    struct Case {
        double metallic, roughness;
        Vec3 kd, ks, reflect;
    };
    const Vec3 base(0.5f, 0.25f, 1.0f);
    const Case cases[] = {
        {1.0, 0.0, Vec3(0.0f), base, base},          // a polished metal: a mirror
        {1.0, 1.0, Vec3(0.0f), base, Vec3(0.0f)},    // a rough metal: no mirror
        {0.0, 0.0, base, Vec3(0.04f), Vec3(0.04f)},  // glossy plastic
        {0.0, 0.5, base, Vec3(0.04f), Vec3(0.01f)},  // satin plastic
    };
    for (const Case& c : cases) {
        TempDir dir;
        GltfAsset a = make_gltf(5123);
        a.doc()["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = c.metallic;
        a.doc()["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = c.roughness;
        const std::string path = a.write_embedded(dir, "m.gltf");
        std::vector<Material> materials;
        load_gltf(path, materials, "here");
        const Material& m = materials.at(0);
        SCOPED_TRACE("metallic " + std::to_string(c.metallic) + " roughness " +
                     std::to_string(c.roughness));
        expect_vec3(m.kd, c.kd.x, c.kd.y, c.kd.z);
        expect_vec3(m.ks, c.ks.x, c.ks.y, c.ks.z);
        expect_vec3(m.reflect, c.reflect.x, c.reflect.y, c.reflect.z);
    }
}

TEST(MeshLoaderGltf, EmissionFromFactorAndStrength) {
    TempDir dir;
    GltfAsset a = make_gltf(5123);
    a.doc()["materials"][0]["emissiveFactor"] = {1.0, 0.5, 0.25};
    a.doc()["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] =
        4.0;
    const std::string path = a.write_embedded(dir, "e.gltf");
    std::vector<Material> materials;
    load_gltf(path, materials, "here");
    expect_vec3(materials.at(0).emission, 4.0f, 2.0f, 1.0f);
    a.doc()["materials"][0]["emissiveFactor"] = {1.0, -0.5, 0.25};
    const std::string bad = a.write_embedded(dir, "bad.gltf");
    const InputError error = expect_input_error([&] { load_gltf(bad, materials, "here"); });
    EXPECT_NE(error.message().find("emissiveFactor"), std::string::npos) << error.message();
}

TEST(MeshLoaderGltf, DoubleSidedMapsOntoTheMaterialsSidedness) {
    // glTF 2.0 §3.9.5: doubleSided defaults to false, a one-sided material.
    TempDir dir;
    GltfAsset a = make_gltf(5123);
    std::vector<Material> materials;
    load_gltf(a.write_embedded(dir, "one.gltf"), materials, "here");
    EXPECT_FALSE(materials.at(0).double_sided);
    a.doc()["materials"][0]["doubleSided"] = true;
    materials.clear();
    load_gltf(a.write_embedded(dir, "two.gltf"), materials, "here");
    EXPECT_TRUE(materials.at(0).double_sided);
}

TEST(MeshLoaderGltf, VertexColoursFromNormalizedBytes) {
    // COLOR_0 as normalized unsigned-byte VEC4 (alpha ignored), appended after the indices.
    TempDir dir;
    GltfAsset a = make_gltf(5123);
    const uint8_t colours[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 51, 102, 255, 0};
    const int colour = a.accessor(colours, 16, 5121, 4, "VEC4");
    a.doc()["accessors"][colour]["normalized"] = true;
    a.doc()["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = colour;
    const std::string path = a.write_embedded(dir, "c.gltf");
    std::vector<Material> materials;
    const TriangleMesh mesh = load_gltf(path, materials, "here");
    ASSERT_EQ(mesh.colors.size(), 4u);
    expect_vec3(mesh.colors[0], 1, 0, 0);
    expect_vec3(mesh.colors[3], 0.2f, 0.4f, 1.0f);
}

TEST(MeshLoaderGltf, BinaryGlbWithUnsignedByteIndices) {
    TempDir dir;
    const std::string path = make_gltf(5121).write_glb(dir, "tri.glb");
    std::vector<Material> materials;
    const TriangleMesh mesh = load_gltf(path, materials, "here");
    ASSERT_EQ(mesh.triangle_count(), 2u);
    EXPECT_EQ(mesh.triangles[1][1], 3u);
    expect_vec3(mesh.positions[1], 1, 0, 0);
}

TEST(MeshLoaderGltf, RequiredExtensionsAreNamedAndRefused) {
    // An extension rayo does not implement (meshopt compression: its accessors have no
    // bufferView, so tinygltf alone reports "invalid bufferView"), as .gltf and as .glb, named
    // among the required ones; Draco (supported) is not named; a used-but-not-required
    // extension is fine.
    for (const bool binary : {false, true}) {
        TempDir dir;
        GltfAsset a = make_gltf(5123);
        a.doc()["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_materials_ior"};
        a.doc()["extensionsRequired"] = {"KHR_draco_mesh_compression", "EXT_meshopt_compression"};
        a.doc()["accessors"][0].erase("bufferView");
        const std::string path =
            binary ? a.write_glb(dir, "meshopt.glb") : a.write_embedded(dir, "meshopt.gltf");
        std::vector<Material> materials;
        const InputError error = expect_input_error([&] { load_gltf(path, materials, "here"); });
        EXPECT_EQ(error.where(), path);
        EXPECT_NE(error.message().find("requires glTF extension(s) EXT_meshopt_compression, "),
                  std::string::npos)
            << error.message();
        EXPECT_NE(error.message().find("does not support"), std::string::npos) << error.message();
    }
    TempDir dir;
    GltfAsset used = make_gltf(5123);
    used.doc()["extensionsUsed"] = {"KHR_materials_ior"};
    const std::string path = used.write_embedded(dir, "used.gltf");
    std::vector<Material> materials;
    EXPECT_EQ(load_gltf(path, materials, "here").triangle_count(), 2u);
}

// The quad of make_gltf compressed with Draco's encoder (no quantization: lossless), with an
// 8-bit colour per corner; the glTF names the Draco attributes by their unique ids and its
// accessors have no bufferView (KHR_draco_mesh_compression).
GltfAsset make_draco_gltf() {
    const float positions[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    const uint8_t colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {51, 102, 255}};
    draco::Mesh mesh;
    mesh.set_num_points(4);
    draco::GeometryAttribute position;
    position.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false,
                  3 * sizeof(float), 0);
    const int pos = mesh.AddAttribute(position, true, 4);
    draco::GeometryAttribute colour;
    colour.Init(draco::GeometryAttribute::COLOR, nullptr, 3, draco::DT_UINT8, true, 3, 0);
    const int col = mesh.AddAttribute(colour, true, 4);
    for (int i = 0; i < 4; ++i) {
        mesh.attribute(pos)->SetAttributeValue(draco::AttributeValueIndex(i), positions[i]);
        mesh.attribute(col)->SetAttributeValue(draco::AttributeValueIndex(i), colours[i]);
    }
    mesh.AddFace({draco::PointIndex(0), draco::PointIndex(1), draco::PointIndex(2)});
    mesh.AddFace({draco::PointIndex(1), draco::PointIndex(3), draco::PointIndex(2)});
    draco::Encoder encoder;
    draco::EncoderBuffer encoded;
    EXPECT_TRUE(encoder.EncodeMeshToBuffer(mesh, &encoded).ok());

    GltfAsset a;
    a.doc().erase("scene");
    a.doc().erase("scenes");
    a.doc()["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    a.doc()["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    const Json draco = {{"bufferView", a.view(encoded.data(), encoded.size())},
                        {"attributes",
                         {{"POSITION", mesh.attribute(pos)->unique_id()},
                          {"COLOR_0", mesh.attribute(col)->unique_id()}}}};
    a.doc()["accessors"] = {
        {{"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"componentType", 5121}, {"normalized", true}, {"count", 4}, {"type", "VEC3"}},
        {{"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}};
    a.node({{"mesh", a.mesh({{"attributes", {{"POSITION", 0}, {"COLOR_0", 1}}},
                             {"indices", 2},
                             {"extensions", {{"KHR_draco_mesh_compression", draco}}}})}},
           false);
    return a;
}

TEST(MeshLoaderGltf, DracoCompressedMeshesDecoded) {
    for (const bool binary : {false, true}) {
        TempDir dir;
        const GltfAsset a = make_draco_gltf();
        const std::string path =
            binary ? a.write_glb(dir, "draco.glb") : a.write_embedded(dir, "draco.gltf");
        std::vector<Material> materials;
        const TriangleMesh mesh = load_gltf(path, materials, "here");
        ASSERT_EQ(mesh.triangle_count(), 2u) << binary;
        ASSERT_EQ(mesh.positions.size(), 4u);
        ASSERT_EQ(mesh.colors.size(), 4u);
        // Draco may reorder the points: each position must keep its own colour, and the two
        // triangles must cover the quad (total area 1).
        float area = 0.0f;
        for (const auto& t : mesh.triangles) {
            area += 0.5f * glm::length(glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                                  mesh.positions[t[2]] - mesh.positions[t[0]]));
        }
        EXPECT_NEAR(area, 1.0f, 1e-6f);
        for (size_t i = 0; i < 4; ++i) {
            const Vec3& p = mesh.positions[i];
            const Vec3 expected = p == Vec3(0, 0, 0)   ? Vec3(1, 0, 0)
                                  : p == Vec3(1, 0, 0) ? Vec3(0, 1, 0)
                                  : p == Vec3(0, 1, 0) ? Vec3(0, 0, 1)
                                                       : Vec3(0.2f, 0.4f, 1.0f);
            expect_vec3(mesh.colors[i], expected.x, expected.y, expected.z, 1e-6f);
        }
    }
}

TEST(MeshLoaderGltf, BadDracoDataNamed) {
    TempDir dir;
    GltfAsset corrupt = make_draco_gltf();
    std::fill(corrupt.bin().begin() + 8, corrupt.bin().end(), uint8_t{0xAB});  // header kept
    std::vector<Material> materials;
    const std::string c = corrupt.write_embedded(dir, "corrupt.gltf");
    InputError error = expect_input_error([&] { load_gltf(c, materials, "here"); });
    EXPECT_EQ(error.where(), c);
    EXPECT_NE(error.message().find("mesh 0 primitive 0 (KHR_draco_mesh_compression)"),
              std::string::npos)
        << error.message();
    GltfAsset missing = make_draco_gltf();
    missing.doc()["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]
                 ["attributes"]["COLOR_0"] = 77;
    const std::string m = missing.write_embedded(dir, "missing.gltf");
    error = expect_input_error([&] { load_gltf(m, materials, "here"); });
    EXPECT_NE(error.message().find("COLOR_0: the Draco data has no attribute 77"),
              std::string::npos)
        << error.message();
    GltfAsset far = make_draco_gltf();
    far.doc()["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]
             ["bufferView"] = 5;
    const std::string f = far.write_embedded(dir, "far.gltf");
    error = expect_input_error([&] { load_gltf(f, materials, "here"); });
    EXPECT_NE(error.message().find("bufferView 5 does not exist"), std::string::npos)
        << error.message();
}

TEST(MeshLoaderGltf, ExternalBinWithUnsignedIntIndices) {
    TempDir dir;
    GltfAsset a = make_gltf(5125);
    const std::string path = a.write_external(dir, "ext.gltf", "data.bin");
    std::vector<Material> materials;
    const TriangleMesh mesh = load_gltf(path, materials, "here");
    ASSERT_EQ(mesh.triangle_count(), 2u);
    EXPECT_EQ(mesh.triangles[0][2], 2u);
}

TEST(MeshLoaderGltf, NodeTrsAndMatrixTransformsApplied) {
    TempDir dir;
    GltfAsset a = make_gltf(5123);
    // Root: translate (10, 0, 0), rotate 90° about z, scale 2; child: matrix translating by
    // (0, 0, 5). Both instance the mesh.
    const double s = std::sqrt(0.5);
    a.doc()["nodes"] = {
        {{"mesh", 0},
         {"translation", {10, 0, 0}},
         {"rotation", {0, 0, s, s}},
         {"scale", {2, 2, 2}},
         {"children", {1}}},
        {{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}}};
    const std::string path = a.write_embedded(dir, "trs.gltf");
    std::vector<Material> materials;
    const TriangleMesh mesh = load_gltf(path, materials, "here");
    ASSERT_EQ(mesh.triangle_count(), 4u);
    ASSERT_EQ(mesh.positions.size(), 8u);
    // (1,0,0) -> scale (2,0,0) -> rotate (0,2,0) -> translate (10,2,0).
    expect_vec3(mesh.positions[1], 10, 2, 0, 1e-5f);
    // Child: (1,0,0) -> (1,0,5) -> parent -> (10,2,10).
    expect_vec3(mesh.positions[5], 10, 2, 10, 1e-5f);
    expect_vec3(mesh.normals[5], 0, 0, 1, 1e-6f);
}

TEST(MeshLoaderGltf, UnsupportedModeRejected) {
    TempDir dir;
    GltfAsset a = make_gltf(5123);
    a.doc()["meshes"][0]["primitives"][0]["mode"] = 5;  // TRIANGLE_STRIP
    const std::string path = a.write_embedded(dir, "strip.gltf");
    std::vector<Material> materials;
    const InputError error = expect_input_error([&] { load_gltf(path, materials, "here"); });
    EXPECT_EQ(error.where(), path);
    EXPECT_NE(error.message().find("unsupported primitive mode 5"), std::string::npos)
        << error.message();
}

TEST(MeshLoaderGltf, IndexOutOfRangeRejected) {
    TempDir dir;
    GltfAsset a = make_gltf(5121);
    a.bin()[96 + 4] = 9;  // the fifth index (after 48 bytes of positions and 48 of normals)
    const std::string path = a.write_glb(dir, "bad.glb");
    std::vector<Material> materials;
    const InputError error = expect_input_error([&] { load_gltf(path, materials, "here"); });
    EXPECT_NE(error.message().find("index 9 out of range"), std::string::npos) << error.message();
}

TEST(MeshLoaderGltf, AccessorBeyondBufferRejected) {
    TempDir dir;
    GltfAsset a = make_gltf(5123);
    a.doc()["accessors"][0]["count"] = 400;
    const std::string path = a.write_embedded(dir, "short.gltf");
    std::vector<Material> materials;
    const InputError error = expect_input_error([&] { load_gltf(path, materials, "here"); });
    EXPECT_EQ(error.where(), path);
}

TEST(MeshLoaderGltf, MalformedAndMissingFilesRejected) {
    TempDir dir;
    const std::string path = dir.write("broken.gltf", "{ \"asset\": ");
    std::vector<Material> materials;
    const InputError broken = expect_input_error([&] { load_gltf(path, materials, "here"); });
    EXPECT_EQ(broken.where(), path);
    EXPECT_NE(broken.message().find("malformed glTF"), std::string::npos);

    const InputError missing = expect_input_error(
        [&] { load_gltf(dir.path() + "/none.glb", materials, "scene.json#/objects/0/file"); });
    EXPECT_EQ(missing.where(), "scene.json#/objects/0/file");
    EXPECT_NE(missing.message().find("none.glb"), std::string::npos);
}

// ---- Helpers ------------------------------------------------------------------------------

TEST(MeshLoaderHelpers, MirrorTransformFlipsWindingAndNormals) {
    TriangleMesh mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.normals = {Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1)};
    mesh.triangles = {{0, 1, 2}};
    mesh.materials = {0};
    transform_mesh(mesh, glm::scale(glm::dmat4(1.0), glm::dvec3(1, 1, -4)));
    EXPECT_EQ(mesh.triangles[0][1], 2u);  // winding reversed
    expect_vec3(mesh.normals[0], 0, 0, -1);
    const Vec3 ng = glm::cross(mesh.positions[mesh.triangles[0][1]] - mesh.positions[0],
                               mesh.positions[mesh.triangles[0][2]] - mesh.positions[0]);
    EXPECT_GT(glm::dot(ng, mesh.normals[0]), 0.0f);  // winding agrees with the normal
}

TEST(MeshLoaderHelpers, NonUniformScaleUsesInverseTranspose) {
    TriangleMesh mesh;
    mesh.positions = {Vec3(0)};
    mesh.normals = {glm::normalize(Vec3(1, 1, 0))};
    transform_mesh(mesh, glm::scale(glm::dmat4(1.0), glm::dvec3(2, 1, 1)));
    expect_vec3(mesh.normals[0], 1.0f / std::sqrt(5.0f), 2.0f / std::sqrt(5.0f), 0, 1e-6f);
}

TEST(MeshLoaderHelpers, VertexNormalsAreAreaWeighted) {
    TriangleMesh mesh;
    // Two faces at vertex 0: a big one in z = 0 (normal +z) and a small one in x = 0 (+x).
    mesh.positions = {Vec3(0), Vec3(3, 0, 0), Vec3(0, 3, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    mesh.triangles = {{0, 1, 2}, {0, 3, 4}};
    compute_vertex_normals(mesh);
    // Area vectors (0,0,9) and (1,0,0): the sum normalized.
    expect_vec3(mesh.normals[0], 1.0f / std::sqrt(82.0f), 0, 9.0f / std::sqrt(82.0f), 1e-6f);
    expect_vec3(mesh.normals[1], 0, 0, 1);
}

}  // namespace
}  // namespace rayo
