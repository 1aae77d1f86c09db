// Tests of PLY, STL and OFF import by rayo's own readers (apps/scene/polygon_file_loader.h), on
// files the tests write: an ASCII PLY with vertex colours and normals, a binary STL, an OFF; the
// errors for truncated, out-of-range, empty and absurd files; and the dispatch of
// import_mesh_file. Many cases were found by fuzz/mesh_fuzz.cpp when assimp read these formats
// (it crashed, hung or reserved gigabytes on them); they stay as tests of the readers that
// replaced it. Each format's own cases: tests/scene/ply_reader_test.cpp, stl_reader_test.cpp,
// off_reader_test.cpp.
#include "apps/scene/polygon_file_loader.h"

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

class PolygonFileLoader : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = std::filesystem::temp_directory_path() /
                ("rayo_polygon_file_test_" + std::to_string(::getpid()) + "_" +
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
            load_polygon_file(path, materials, "scene.json#/objects/0/file");
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

TEST_F(PolygonFileLoader, AsciiPlyKeepsVertexColoursAndNormals) {
    const std::string path = write("quad.ply", kPlyHeader + kPlyVertices + "4 0 1 2 3\n");
    std::vector<Material> materials;
    MeshImportStats stats;
    const TriangleMesh mesh = load_polygon_file(path, materials, "here", &stats);
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

TEST_F(PolygonFileLoader, BinaryStlJoinsCornersAndShadesFlat) {
    // Two triangles of a quad: STL repeats the two shared corners.
    const std::string path =
        write("quad.stl", binary_stl({{0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 0, 1, 1, 0, 0, 1, 0}}));
    std::vector<Material> materials;
    const TriangleMesh mesh = load_polygon_file(path, materials, "here");
    EXPECT_EQ(mesh.triangle_count(), 2u);
    EXPECT_EQ(mesh.positions.size(), 4u);
    EXPECT_TRUE(mesh.normals.empty());  // flat: the facet normals are dropped
    EXPECT_TRUE(mesh.colors.empty());
}

TEST_F(PolygonFileLoader, OffAndImportMeshFileDispatch) {
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

TEST_F(PolygonFileLoader, TruncatedPlyNamesTheFileAndTheElement) {
    // The header declares 4 vertices; the file ends after the second.
    const std::string path = write("cut.ply", kPlyHeader + kPlyVertices.substr(0, 28));
    const InputError e = error_of(path);
    EXPECT_EQ(e.where().rfind(path, 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("PLY"), std::string::npos) << e.what();
}

TEST_F(PolygonFileLoader, AbsurdPlyCountsRefusedBeforeReading) {
    // Two billion vertices declared in a file of a few hundred bytes: refused at the header's
    // line (assimp, which read PLY for rayo before, reserved memory for every one of them first).
    std::string header = kPlyHeader;
    header.replace(header.find("element vertex 4"), 16, "element vertex 2000000000");
    const std::string path = write("huge.ply", header + kPlyVertices + "4 0 1 2 3\n");
    const InputError e = error_of(path);
    EXPECT_EQ(e.where(), path + ":4") << e.what();
    EXPECT_NE(e.message().find("declares 2000000000"), std::string::npos) << e.message();
}

TEST_F(PolygonFileLoader, FaceIndexOutOfRangeRefused) {
    const std::string path = write("far.ply", kPlyHeader + kPlyVertices + "4 0 1 2 7\n");
    const InputError e = error_of(path);
    EXPECT_EQ(e.where(), path + ":21") << e.what();
    EXPECT_EQ(e.message(),
              "PLY element 'face' instance 0: vertex index 7 out of range (the file has 4 "
              "vertices)");
}

TEST_F(PolygonFileLoader, OffIndexOutOfRangeAndAbsurdCountsRefusedAtTheirLine) {
    // assimp clamped the index 99999 to the last vertex (the same image as the valid triangle)
    // and reserved 2^31 vertices before reading one (bad_alloc): both refused at path:line.
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
    const InputError glued = error_of(write("glued.off", "OFF2147483648 1 0\n0 0 0\n3 0 0 0\n"));
    EXPECT_NE(glued.message().find("declares 2147483648 vertices"), std::string::npos)
        << glued.message();
    const InputError wide = error_of(write("wide.off", "OFF2488555555555555555555555 4\n"));
    EXPECT_EQ(wide.message(),
              "expected the vertex and face counts, got "
              "'2488555555555555555555555 4'");
    const InputError count = error_of(huge);
    EXPECT_EQ(count.where(), huge + ":2") << count.what();
    EXPECT_NE(count.message().find("declares 2147483648 vertices"), std::string::npos)
        << count.message();
}

TEST_F(PolygonFileLoader, EmptyGarbageAndPointOnlyFilesRefused) {
    const std::string empty = write("empty.stl", "");
    EXPECT_NE(error_of(empty).message().find("empty STL"), std::string::npos);
    const std::string garbage = write("garbage.ply", "this is not a PLY file\n");
    const InputError g = error_of(garbage);
    EXPECT_EQ(g.where().rfind(garbage, 0), 0u) << g.what();
    EXPECT_EQ(g.message(),
              "not a PLY file: its first line must be 'ply', got 'this is not a PLY file'");
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

// assimp's ASCII STL reader threw on these and leaked the mesh it was building (LeakSanitizer;
// found by fuzz/mesh_fuzz.cpp): refused at their line. A solid without facets is read (the file's
// other solids count); a facet of four vertices is refused (assimp skipped the fourth).
TEST_F(PolygonFileLoader, MalformedAsciiStlRefusedAtItsLine) {
    const std::string facet =
        " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
        "   vertex 0 1 0\n  endloop\n endfacet\n";
    std::string bad_number = "solid t\n" + facet + "endsolid t\n";
    bad_number.replace(bad_number.find("vertex 1 0 0"), 12, "vertex 1 0 x");
    const std::string number = write("number.stl", bad_number);
    const InputError n = error_of(number);
    EXPECT_EQ(n.where(), number + ":5") << n.what();
    EXPECT_EQ(n.message(), "STL vertex: expected 3 numbers, got 'x'");
    const std::string cut = write("cut.stl",
                                  "solid t\n facet normal 0 0 1\n  outer loop\n"
                                  "   vertex 0 0 0\n   vertex 1 0");
    const InputError c = error_of(cut);
    EXPECT_EQ(c.where(), cut + ":5") << c.what();
    EXPECT_EQ(c.message(), "STL vertex: expected 3 numbers, got ''");
    std::vector<Material> materials;
    const std::string empty =
        write("empty_solid.stl", "solid t\n" + facet + "endsolid t\n" + "solid u\nendsolid u\n");
    EXPECT_EQ(load_polygon_file(empty, materials, "s.json").triangles.size(), 1u);
    std::string lone = "solid t\n" + facet + " facet normal 0 0 1\nendsolid t\n";
    const std::string lone_normal = write("lone_normal.stl", lone);
    const InputError l = error_of(lone_normal);
    EXPECT_EQ(l.where(), lone_normal + ":10") << l.what();
    EXPECT_EQ(l.message(), "STL: expected 'outer', got 'endsolid'");
    // A NUL byte is not a blank: the word it is in is named, escaped.
    std::string nul = "solid t\n" + facet + facet + "endsolid t\n";
    nul[nul.rfind("outer loop")] = '\0';
    EXPECT_EQ(error_of(write("nul.stl", nul)).message(), "STL: expected 'outer', got '\\x00uter'");
    std::string four = "solid t\n" + facet + "endsolid t\n";
    four.insert(four.find("  endloop"), "   vertex 9 9 9\n");
    const std::string four_path = write("four.stl", four);
    const InputError f = error_of(four_path);
    EXPECT_EQ(f.where(), four_path + ":7") << f.what();
    EXPECT_EQ(f.message(), "STL: a facet has 3 vertices, this one more");
}

// assimp's ASCII PLY reader threw on a value that is not a number and leaked the mesh (found by
// fuzz/mesh_fuzz.cpp): refused at its line, naming the element, instance and property.
TEST_F(PolygonFileLoader, AsciiPlyValueThatIsNotANumberRefusedAtItsLine) {
    std::string vertices = kPlyVertices;
    vertices.replace(vertices.find("1 0 0 0 0 1"), 11, "1 0 0 0'0 1");
    const std::string path = write("quote.ply", kPlyHeader + vertices + "4 0 1 2 3\n");
    const InputError e = error_of(path);
    EXPECT_EQ(e.where(), path + ":18") << e.what();
    EXPECT_EQ(e.message(), "PLY element 'vertex' instance 1: property 'nx': '0'0' is not a number");
}

// A binary PLY whose header has lost its end_header line: assimp read on into the body and died
// (SIGSEGV; found by fuzz/mesh_fuzz.cpp). Refused, as are the other damaged headers it found.
TEST_F(PolygonFileLoader, PlyHeaderWithoutItsEndRefused) {
    const std::string path = write("endless.ply",
                                   "ply\nformat binary_little_endian 1.0\nelement vertex 4\n"
                                   "prod_header\n" +
                                       std::string(64, '\0') + "\x03\x01\x02");
    const InputError e = error_of(path);
    EXPECT_EQ(e.where(), path) << e.what();
    EXPECT_EQ(e.message(), "PLY header without its end_header line (truncated or corrupt)");
    std::string inside = kPlyHeader + kPlyVertices + "4 0 1 2 3\n";
    inside.insert(inside.find("end_header"), "prope");
    EXPECT_EQ(error_of(write("inside.ply", inside)).message(),
              "PLY header without its end_header line (truncated or corrupt)");
    std::string format = kPlyHeader + kPlyVertices + "4 0 1 2 3\n";
    format.replace(format.find("ascii"), 5, "binary_littoperty");
    EXPECT_EQ(error_of(write("format.ply", format)).message(),
              "PLY format 'binary_littoperty': expected ascii, binary_little_endian or "
              "binary_big_endian");
    std::string type = kPlyHeader + kPlyVertices + "4 0 1 2 3\n";
    type.replace(type.find("property float y"), 16, "property liat y");
    const InputError t = error_of(write("type.ply", type));
    EXPECT_EQ(t.where(), m_dir.string() + "/type.ply:6") << t.what();
    EXPECT_EQ(t.message().rfind("PLY property type 'liat' is not a PLY type", 0), 0u);
    std::string name = kPlyHeader + kPlyVertices + "4 0 1 2 3\n";
    name.replace(name.find("element face 1"), 14, "element 2147483648face 1");
    EXPECT_EQ(error_of(write("name.ply", name)).message(),
              "PLY element name '2147483648face': expected a word");
    std::string glued_line = kPlyHeader + kPlyVertices + "4 0 1 2 3\n";
    glued_line.replace(glued_line.find("blue\nelement"), 5, "blueA");
    const InputError g = error_of(write("glued_line.ply", glued_line));
    EXPECT_EQ(g.where(), m_dir.string() + "/glued_line.ply:13") << g.what();
    EXPECT_EQ(g.message(),
              "PLY header: expected property TYPE NAME, got 'property uchar blueAelement "
              "face 1'");
    std::string word = kPlyHeader + kPlyVertices + "4 0 1 2 3\n";
    word.replace(word.find("property uchar red"), 18, "proper alphaar red");
    const InputError w = error_of(write("word.ply", word));
    EXPECT_EQ(w.where(), m_dir.string() + "/word.ply:11") << w.what();
    EXPECT_EQ(w.message().rfind("PLY header line starts with 'proper'", 0), 0u) << w.message();
    std::string glued = kPlyHeader + kPlyVertices + "4 0 1 2 3\n";
    glued[glued.find("end_header") + 10] = '\x1a';
    EXPECT_EQ(error_of(write("glued.ply", glued)).message(),
              "PLY header: end_header must end its line");
}

// Positions come from an element named "vertex" only: a misspelt name (found by
// fuzz/mesh_fuzz.cpp, binary) ended in std::bad_alloc inside assimp after a reservation of
// gigabytes.
TEST_F(PolygonFileLoader, PlyWithoutAVertexElementOfPositionsRefused) {
    const std::string expected =
        "PLY header: no element 'vertex' with properties x, y and z (the positions a mesh needs)";
    std::string misspelt = kPlyHeader + kPlyVertices + "4 0 1 2 3\n";
    misspelt.replace(misspelt.find("element vertex"), 14, "element vertccccex");
    EXPECT_EQ(error_of(write("misspelt.ply", misspelt)).message(), expected);
    std::string no_z = kPlyHeader + kPlyVertices + "4 0 1 2 3\n";
    no_z.replace(no_z.find("property float z"), 16, "property float w");
    EXPECT_EQ(error_of(write("no_z.ply", no_z)).message(), expected);
    const std::string binary =
        "ply\nformat binary_little_endian 1.0\nelement blueex 1\nproperty float x\n"
        "property float y\nproperty float z\nend_header\n" +
        std::string(12, '\0');
    EXPECT_EQ(error_of(write("binary.ply", binary)).message(), expected);
}

// A face whose list count is 0 reached assimp's post-processing, which asserted (SIGABRT; found
// by fuzz/mesh_fuzz.cpp); still refused, at its line.
TEST_F(PolygonFileLoader, FaceWithoutVerticesRefused) {
    const std::string path =
        write("empty_face.ply", kPlyHeader.substr(0, kPlyHeader.find("element face 1")) +
                                    "element face 2\nproperty list uchar int vertex_indices\n"
                                    "end_header\n" +
                                    kPlyVertices + "3 0 1 2\n0\n");
    const InputError e = error_of(path);
    EXPECT_EQ(e.where(), path + ":22") << e.what();
    EXPECT_EQ(e.message(), "PLY element 'face' instance 1: a face of no vertices");
}

// An OFF face line cut short: assimp read on past it (SIGSEGV; found by fuzz/mesh_fuzz.cpp).
TEST_F(PolygonFileLoader, OffFaceOrVertexCutShortRefusedAtItsLine) {
    const std::string face = write("face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3t 0 1\n");
    const InputError f = error_of(face);
    EXPECT_EQ(f.where(), face + ":6") << f.what();
    EXPECT_EQ(f.message(), "face 0: expected its vertex count (1 or more)");
    const std::string vertex = write("vertex.off", "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n");
    const InputError v = error_of(vertex);
    EXPECT_EQ(v.where(), vertex + ":4") << v.what();
    EXPECT_EQ(v.message(), "vertex 1: expected 3 numbers (x y z), got 2");
    // Coordinates are whole numbers: assimp read "1-5" otherwise (SIGSEGV).
    const std::string glued = write("glued.off", "OFF\n3 1 0\n0 0 0\n1-5 0 0\n0 1 0\n3 0 1 2\n");
    EXPECT_EQ(error_of(glued).message(), "vertex 1: '1-5' is not a number");
    // The variants with colours (COFF) and the others are checked alike.
    const std::string coff = write("face.coff.off",
                                   "COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n"
                                   "3 0 1\n");
    const InputError c = error_of(coff);
    EXPECT_EQ(c.where(), coff + ":6") << c.what();
    EXPECT_EQ(c.message(), "face 0: expected 3 vertex indices, got 2");
}

TEST_F(PolygonFileLoader, NonFiniteAndHugeCoordinatesRefused) {
    const std::string path =
        write("nan.ply", kPlyHeader +
                             "0 0 0 0 0 1 0 0 0\n1e30 0 0 0 0 1 0 0 0\n"
                             "1 1 0 0 0 1 0 0 0\n0 1 0 0 0 1 0 0 0\n4 0 1 2 3\n");
    const InputError e = error_of(path);
    EXPECT_NE(e.message().find("coordinates must be"), std::string::npos) << e.message();
    // A NaN in y (or z) was accepted: the magnitude test took the largest of |x|, |y|, |z| with
    // glm::max, which drops a NaN there (found by fuzz/mesh_fuzz.cpp).
    const std::string ny =
        write("nan_y.ply", kPlyHeader +
                               "0 0 0 0 0 1 0 0 0\n1 nan 0 0 0 1 0 0 0\n"
                               "1 1 0 0 0 1 0 0 0\n0 1 0 0 0 1 0 0 0\n4 0 1 2 3\n");
    const InputError n = error_of(ny);
    EXPECT_EQ(n.where(), ny + ":18") << n.what();
    EXPECT_EQ(n.message().rfind("PLY element 'vertex' instance 1: coordinates must be", 0), 0u)
        << n.message();
}

}  // namespace
}  // namespace rayo
