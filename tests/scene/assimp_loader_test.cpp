// Tests of PLY, STL and OFF import through assimp (apps/scene/assimp_loader.h), on files the tests
// write: an ASCII PLY with vertex colours and normals, a binary STL, an OFF; the errors for
// truncated, out-of-range, empty and absurd files; and the dispatch of import_mesh_file.
#include "apps/scene/assimp_loader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec3;

class AssimpLoader : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = std::filesystem::temp_directory_path() /
                ("rayo_assimp_test_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(m_dir);
    }
    void TearDown() override { std::filesystem::remove_all(m_dir); }
    std::string write(const std::string& name, const std::string& bytes) const {
        const auto file = m_dir / name;
        std::ofstream(file, std::ios::binary) << bytes;
        return file.string();
    }
    InputError error_of(const std::string& path) const {
        std::vector<Material> materials;
        try {
            load_assimp_mesh(path, materials, "scene.json#/objects/0/file");
        } catch (const InputError& e) {
            return e;
        }
        ADD_FAILURE() << "no InputError for " << path;
        return InputError("", "");
    }
    std::filesystem::path m_dir;
};

// A unit quad in z = 0 as one 4-corner face (triangulated on import), a colour and a +z normal
// per vertex.
const std::string kPlyHeader =
    "ply\nformat ascii 1.0\ncomment written by the test\nelement vertex 4\n"
    "property float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
const std::string kPlyVertices =
    "0 0 0 0 0 1 255 0 0\n1 0 0 0 0 1 0 255 0\n1 1 0 0 0 1 0 0 255\n0 1 0 0 0 1 51 102 255\n";

// A binary STL: an 80-byte header, the triangle count, then per triangle a normal, three
// corners (floats) and a 2-byte attribute.
std::string binary_stl(const std::vector<std::array<float, 9>>& triangles) {
    std::string out(80, ' ');
    const auto count = static_cast<uint32_t>(triangles.size());
    out.append(reinterpret_cast<const char*>(&count), 4);
    for (const auto& t : triangles) {
        const float normal[3] = {0, 0, 1};
        out.append(reinterpret_cast<const char*>(normal), 12);
        out.append(reinterpret_cast<const char*>(t.data()), 36);
        out.append(2, '\0');
    }
    return out;
}

TEST_F(AssimpLoader, AsciiPlyKeepsVertexColoursAndNormals) {
    const std::string path = write("quad.ply", kPlyHeader + kPlyVertices + "4 0 1 2 3\n");
    std::vector<Material> materials;
    MeshImportStats stats;
    const TriangleMesh mesh = load_assimp_mesh(path, materials, "here", &stats);
    ASSERT_EQ(mesh.triangle_count(), 2u);
    ASSERT_EQ(mesh.positions.size(), 4u);
    ASSERT_EQ(mesh.colors.size(), 4u);
    ASSERT_EQ(mesh.normals.size(), 4u);
    ASSERT_EQ(materials.size(), 1u);
    EXPECT_EQ(materials[0].name, "default");
    EXPECT_EQ(mesh.materials, std::vector<uint32_t>(2, 0u));
    EXPECT_EQ(stats.degenerate_triangles, 0u);
    // Each position keeps its own colour (the bytes scaled to [0, 1]) and its normal.
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3& p = mesh.positions[i];
        const Vec3 expected = p == Vec3(0, 0, 0)   ? Vec3(1, 0, 0)
                              : p == Vec3(1, 0, 0) ? Vec3(0, 1, 0)
                              : p == Vec3(1, 1, 0) ? Vec3(0, 0, 1)
                                                   : Vec3(0.2f, 0.4f, 1.0f);
        expect_vec3(mesh.colors[i], expected.x, expected.y, expected.z, 1e-6f);
        expect_vec3(mesh.normals[i], 0, 0, 1);
    }
}

TEST_F(AssimpLoader, BinaryStlJoinsCornersAndShadesFlat) {
    // Two triangles of a quad: STL repeats the two shared corners.
    const std::string path =
        write("quad.stl", binary_stl({{0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 0, 1, 1, 0, 0, 1, 0}}));
    std::vector<Material> materials;
    const TriangleMesh mesh = load_assimp_mesh(path, materials, "here");
    EXPECT_EQ(mesh.triangle_count(), 2u);
    EXPECT_EQ(mesh.positions.size(), 4u);
    EXPECT_TRUE(mesh.normals.empty());  // flat: the facet normals are dropped
    EXPECT_TRUE(mesh.colors.empty());
}

TEST_F(AssimpLoader, OffAndImportMeshFileDispatch) {
    const std::string off = write("tri.OFF", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    std::vector<Material> materials;
    MeshImportOptions options;
    options.where = "here";
    options.transform = glm::dmat4(2.0);
    options.transform[3][3] = 1.0;
    const ImportedMesh imported = import_mesh_file(off, materials, options);
    ASSERT_EQ(imported.mesh.triangle_count(), 1u);
    EXPECT_TRUE(is_mesh_file(off));
    EXPECT_TRUE(is_mesh_file("a.ply") && is_mesh_file("B.STL"));
    EXPECT_FALSE(is_mesh_file("a.fbx"));
    bool has_scaled = false;
    for (const Vec3& p : imported.mesh.positions) has_scaled |= p == Vec3(2, 0, 0);
    EXPECT_TRUE(has_scaled);
}

TEST_F(AssimpLoader, TruncatedPlyNamesTheFileAndTheElement) {
    // The header declares 4 vertices; the file ends after the second.
    const std::string path = write("cut.ply", kPlyHeader + kPlyVertices.substr(0, 28));
    const InputError e = error_of(path);
    EXPECT_EQ(e.where().rfind(path, 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("PLY"), std::string::npos) << e.what();
}

TEST_F(AssimpLoader, AbsurdPlyCountsRefusedBeforeReading) {
    // Two billion vertices declared in a file of a few hundred bytes: refused at the header's
    // line (assimp would reserve memory for every one of them first).
    std::string header = kPlyHeader;
    header.replace(header.find("element vertex 4"), 16, "element vertex 2000000000");
    const std::string path = write("huge.ply", header + kPlyVertices + "4 0 1 2 3\n");
    const InputError e = error_of(path);
    EXPECT_EQ(e.where(), path + ":4") << e.what();
    EXPECT_NE(e.message().find("declares 2000000000"), std::string::npos) << e.message();
}

TEST_F(AssimpLoader, FaceIndexOutOfRangeRefused) {
    const std::string path = write("far.ply", kPlyHeader + kPlyVertices + "4 0 1 2 7\n");
    const InputError e = error_of(path);
    EXPECT_EQ(e.where(), path) << e.what();
    EXPECT_NE(e.message().find("vertex index 7 out of range"), std::string::npos) << e.message();
}

TEST_F(AssimpLoader, OffIndexOutOfRangeAndAbsurdCountsRefusedAtTheirLine) {
    // assimp clamps the index 99999 to the last vertex (the same image as the valid triangle)
    // and reserves 2^31 vertices before reading one (bad_alloc): both refused at path:line.
    const std::string far = write("far.off",
                                  "OFF\n# a comment\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n"
                                  "3 0 1 99999\n");
    const InputError index = error_of(far);
    EXPECT_EQ(index.where(), far + ":7") << index.what();
    EXPECT_NE(index.message().find("face 0: vertex index 99999 out of range (the file has 3 "
                                   "vertices)"),
              std::string::npos)
        << index.message();
    const std::string huge = write("huge.off", "OFF\n2147483648 1 0\n0 0 0\n3 0 0 0\n");
    const InputError count = error_of(huge);
    EXPECT_EQ(count.where(), huge + ":2") << count.what();
    EXPECT_NE(count.message().find("declares 2147483648 vertices"), std::string::npos)
        << count.message();
}

TEST_F(AssimpLoader, EmptyGarbageAndPointOnlyFilesRefused) {
    const std::string empty = write("empty.stl", "");
    EXPECT_NE(error_of(empty).message().find("empty STL"), std::string::npos);
    const std::string garbage = write("garbage.ply", "this is not a PLY file\n");
    const InputError g = error_of(garbage);
    EXPECT_EQ(g.where().rfind(garbage, 0), 0u) << g.what();
    EXPECT_NE(g.message().find("malformed PLY"), std::string::npos) << g.message();
    // Triangles counted in the header, not present: a binary STL cut short.
    std::string cut = binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}});
    cut[80] = 9;  // nine triangles declared, one present
    const InputError c = error_of(write("cut.stl", cut));
    EXPECT_NE(c.message().find("binary STL declares 9 triangles, which take 534 bytes, but the "
                               "file has 134"),
              std::string::npos)
        << c.message();
    const std::string points =
        write("points.ply",
              "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
              "property float z\nend_header\n0 0 0\n1 1 1\n");
    EXPECT_NE(error_of(points).message().find("no (non-degenerate) triangles"), std::string::npos);
}

TEST_F(AssimpLoader, NonFiniteAndHugeCoordinatesRefused) {
    const std::string path =
        write("nan.ply", kPlyHeader +
                             "0 0 0 0 0 1 0 0 0\n1e30 0 0 0 0 1 0 0 0\n"
                             "1 1 0 0 0 1 0 0 0\n0 1 0 0 0 1 0 0 0\n4 0 1 2 3\n");
    const InputError e = error_of(path);
    EXPECT_NE(e.message().find("coordinates must be"), std::string::npos) << e.message();
}

}  // namespace
}  // namespace rayo
