// Tests of rayo's STL reader (apps/scene/stl_reader.h) on files the tests generate: the same two
// triangles as ASCII and binary read alike with their shared corners joined; binary headers that
// begin with "solid"; several solids; and each refusal with its place.
#include "apps/scene/stl_reader.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec3;
using Triangle = std::array<float, 9>;

// The two triangles of the unit quad in z = 0, sharing the corners (0, 0, 0) and (1, 1, 0).
const std::vector<Triangle> kQuad = {{0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 0, 1, 1, 0, 0, 1, 0}};

// A binary STL (80-byte header, count, 50 bytes a triangle), little-endian as the format says
// (the test machine's order: checked below).
std::string binary_stl(const std::vector<Triangle>& triangles,
                       const std::string& header = std::string(80, ' ')) {
    std::string out = header;
    out.resize(80, ' ');
    const auto count = static_cast<uint32_t>(triangles.size());
    out.append(reinterpret_cast<const char*>(&count), 4);
    for (const Triangle& t : triangles) {
        const float normal[3] = {0, 0, 1};
        out.append(reinterpret_cast<const char*>(normal), 12);
        out.append(reinterpret_cast<const char*>(t.data()), 36);
        out.append(2, '\0');
    }
    return out;
}

std::string ascii_facet(const Triangle& t) {
    std::string out = "  facet normal 0 0 1\n    outer loop\n";
    for (int k = 0; k < 3; ++k) {
        out += "      vertex " + std::to_string(t[3 * k]) + " " + std::to_string(t[3 * k + 1]) +
               " " + std::to_string(t[3 * k + 2]) + "\n";
    }
    return out + "    endloop\n  endfacet\n";
}

std::string ascii_stl(const std::vector<Triangle>& triangles, const std::string& name = "quad") {
    std::string out = "solid " + name + "\n";
    for (const Triangle& t : triangles) out += ascii_facet(t);
    return out + "endsolid " + name + "\n";
}

InputError error_of(const std::string& bytes) {
    try {
        read_stl(bytes, "m.stl");
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError for\n" << bytes;
    return InputError("", "");
}

TEST(StlReader, AsciiAndBinaryReadTheSameTrianglesWithSharedCornersJoined) {
    const uint32_t one = 1;
    ASSERT_EQ(reinterpret_cast<const unsigned char*>(&one)[0], 1) << "the test writes LE bytes";
    for (const std::string& bytes : {ascii_stl(kQuad), binary_stl(kQuad)}) {
        const PolygonMesh mesh = read_stl(bytes, "quad.stl");
        ASSERT_EQ(mesh.positions.size(), 4u);  // six corners, four places
        // Numbered in the order of first use.
        expect_vec3(mesh.positions[0], 0, 0, 0);
        expect_vec3(mesh.positions[1], 1, 0, 0);
        expect_vec3(mesh.positions[2], 1, 1, 0);
        expect_vec3(mesh.positions[3], 0, 1, 0);
        EXPECT_EQ(mesh.corners, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
        EXPECT_EQ(mesh.face_ends, (std::vector<uint32_t>{3, 6}));
        EXPECT_TRUE(mesh.normals.empty());  // facet normals dropped: flat, or smooth on request
        EXPECT_TRUE(mesh.colors.empty());
    }
    // -0 and 0 are one place.
    const PolygonMesh zeros =
        read_stl(binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {-0.0f, 0, -0.0f, 0, 1, 0, 0, 0, 1}}),
                 "zeros.stl");
    EXPECT_EQ(zeros.positions.size(), 4u);
}

// A binary header may begin with "solid": the file is binary when its size is exactly the binary
// size its count gives, ASCII otherwise.
TEST(StlReader, SolidAtTheStartOfABinaryHeaderAndSeveralAsciiSolids) {
    const PolygonMesh binary = read_stl(binary_stl(kQuad, "solid exported by a CAD tool"), "b.stl");
    EXPECT_EQ(binary.face_ends.size(), 2u);
    const PolygonMesh two = read_stl(
        "\n  " + ascii_stl({kQuad[0]}, "a") + ascii_stl({}, "empty") + ascii_stl({kQuad[1]}, "b"),
        "two.stl");
    EXPECT_EQ(two.face_ends.size(), 2u);
    EXPECT_EQ(two.positions.size(), 4u);
    // CRLF line ends, keywords on one line.
    const PolygonMesh crlf = read_stl(
        "solid x\r\nfacet normal 0 0 1 outer loop vertex 0 0 0 vertex 1 0 0 vertex 0 1 0 "
        "endloop endfacet\r\nendsolid\r\n",
        "crlf.stl");
    EXPECT_EQ(crlf.corners, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(StlReader, AsciiMistakesRefusedAtTheirLine) {
    struct Case {
        std::string text;
        std::string where;
        std::string message;
    };
    const std::string facet = ascii_facet(kQuad[0]);
    std::string no_loop = "solid t\n" + facet + "endsolid t\n";
    no_loop.replace(no_loop.find("outer loop"), 10, "loop");
    const std::vector<Case> cases = {
        {"solid t\n" + facet, "m.stl:8",
         "STL: the file ends inside a solid, before 'endsolid' (truncated?)"},
        {"solid t\n" + facet + "endsolid t\ngarbage\n", "m.stl:10",
         "STL: expected 'solid' or the end of the file, got 'garbage'"},
        {"solid t\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n", "m.stl:4",
         "STL: the file ends where 'vertex' was expected (truncated?)"},
        {no_loop, "m.stl:3", "STL: expected 'outer', got 'loop'"},
        {"solid t\n  facet normal 0 0 one\n", "m.stl:2",
         "STL normal: expected 3 numbers, got 'one'"},
        {"solid t\n  face normal 0 0 1\n", "m.stl:2",
         "STL: expected 'facet' or 'endsolid', got 'face'"},
        {"solid t\n" + facet.substr(0, facet.find("    endloop")) + "    endfacet\n", "m.stl:7",
         "STL: expected 'endloop', got 'endfacet'"},
        {"solid t\n  facet normal 0 0 1\n    outer loop\n      vertex 0 1e30 0\n", "m.stl:4",
         "STL vertex: coordinates must be a finite number (in float range) of magnitude <= "
         "1e18, so that its square fits a float"},
        {"solid t\n  facet normal 0 0 1\n    outer loop\n      vertex 0 nan 0\n", "m.stl:4",
         "STL vertex: coordinates must be a finite number (in float range) of magnitude <= "
         "1e18, so that its square fits a float"},
    };
    for (const Case& c : cases) {
        const InputError e = error_of(c.text);
        EXPECT_EQ(e.where(), c.where) << c.text;
        EXPECT_EQ(e.message(), c.message) << c.text;
    }
}

TEST(StlReader, BinaryMistakesRefusedByTheirTriangle) {
    std::string cut = binary_stl(kQuad);
    cut.resize(cut.size() - 1);
    EXPECT_EQ(error_of(cut).message(),
              "binary STL declares 2 triangles, which take 184 bytes, but the file has 183");
    EXPECT_EQ(error_of("not an STL").message(),
              "binary STL shorter than its 84-byte header (10 bytes)");
    Triangle far = kQuad[1];
    far[7] = std::numeric_limits<float>::infinity();
    const InputError e = error_of(binary_stl({kQuad[0], far}));
    EXPECT_EQ(e.where(), "m.stl");
    EXPECT_EQ(e.message(),
              "binary STL triangle 1: coordinates must be a finite number (in float range) of "
              "magnitude <= 1e18, so that its square fits a float");
    // Bytes after the last triangle are ignored, as before.
    EXPECT_EQ(read_stl(binary_stl(kQuad) + "trailing", "t.stl").face_ends.size(), 2u);
}

}  // namespace
}  // namespace rayo
