// Tests of rayo's OFF reader (apps/scene/off_reader.h) on files the tests generate: counts on
// the keyword's line, in its word or on their own line, comments; the NOFF, COFF and STOFF
// variants and their combinations; face colours; and each refusal with its line.
#include "apps/scene/off_reader.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "core/shapes/polygon_triangulation.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec3;

InputError error_of(const std::string& bytes) {
    try {
        read_off(bytes, "m.off");
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError for\n" << bytes;
    return InputError("", "");
}

TEST(OffReader, CountsWhereverTheKeywordLeavesThemAndComments) {
    for (const std::string& text :
         {std::string("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"),
          std::string("# a comment first\nOFF 4 1 0 # counts on the keyword's line\n\n"
                      "0 0 0\n1 0 0 # the second vertex\n1 1 0\n0 1 0\n4 0 1 2 3\n"),
          std::string("OFF4 1\r\n0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n4 0 1 2 3\r\n")}) {
        const PolygonMesh mesh = read_off(text, "quad.off");
        ASSERT_EQ(mesh.positions.size(), 4u) << text;
        expect_vec3(mesh.positions[2], 1, 1, 0);
        EXPECT_EQ(mesh.corners, (std::vector<uint32_t>{0, 1, 2, 3})) << text;
        EXPECT_EQ(mesh.face_ends, (std::vector<uint32_t>{4})) << text;
        EXPECT_TRUE(mesh.normals.empty() && mesh.colors.empty());
    }
}

// Geomview's order on a vertex line: x y z, the normal (N), the colour (C: 3 or 4 numbers), the
// texture coordinates (ST). Integer colours are bytes when one exceeds 1; float colours are kept.
TEST(OffReader, VariantsWithNormalsColoursAndTextureCoordinates) {
    const PolygonMesh noff =
        read_off("NOFF\n3 1 0\n0 0 0 0 0 2\n1 0 0 0 0 1\n0 1 0 0 0 0\n3 0 1 2\n", "n.off");
    ASSERT_EQ(noff.normals.size(), 3u);
    expect_vec3(noff.normals[0], 0, 0, 1);
    expect_vec3(noff.normals[2], 0, 0, 0);  // zero: shaded with the geometric normal
    const PolygonMesh bytes = read_off(
        "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 51 0 255\n0 1 0 0 0 255\n3 0 1 2\n", "c.off");
    ASSERT_EQ(bytes.colors.size(), 3u);
    expect_vec3(bytes.colors[0], 1, 0, 0);
    expect_vec3(bytes.colors[1], 0, 0.2, 0, 1e-6);
    const PolygonMesh floats =
        read_off("COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 0.5 0 1\n0 1 0 0 0 1\n3 0 1 2\n", "f.off");
    expect_vec3(floats.colors[0], 1, 0, 0);
    expect_vec3(floats.colors[1], 0, 0.5, 0);
    const PolygonMesh all = read_off(
        "STCNOFF 3 1 0\n0 0 0 0 0 1 0.5 0.5 0.5 1 0 0\n1 0 0 0 0 1 0.5 0.5 0.5 1 1 0\n"
        "0 1 0 0 0 1 0.5 0.5 0.5 0 1\n3 0 1 2\n",
        "all.off");
    ASSERT_EQ(all.normals.size(), 3u);
    ASSERT_EQ(all.colors.size(), 3u);
    expect_vec3(all.positions[1], 1, 0, 0);
    expect_vec3(all.colors[2], 0.5, 0.5, 0.5);
    // A face's colour after its indices (a colour-map index, r g b or r g b a) is not read.
    const PolygonMesh face_colours =
        read_off("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1 0 0\n3 2 1 0 7\n", "fc.off");
    EXPECT_EQ(face_colours.corners, (std::vector<uint32_t>{0, 1, 2, 2, 1, 0}));
}

TEST(OffReader, MistakesRefusedAtTheirLine) {
    const std::string triangle = "0 0 0\n1 0 0\n0 1 0\n";
    struct Case {
        std::string text;
        std::string where;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"# only a comment\n", "m.off", "OFF file without the keyword OFF (only comments)"},
        {"3 1 0\n" + triangle + "3 0 1 2\n", "m.off:1",
         "not an OFF file: expected the keyword OFF (or COFF, NOFF, CNOFF, STOFF, ...) first, "
         "got '3'"},
        {"NCOFF\n3 1 0\n", "m.off:1",
         "not an OFF file: expected the keyword OFF (or COFF, NOFF, CNOFF, STOFF, ...) first, "
         "got 'NCOFF'"},
        {"4OFF\n3 1 0\n", "m.off:1",
         "OFF variant '4OFF' (4-D or n-D vertices) is not read; expected OFF, COFF, NOFF, "
         "CNOFF, STOFF, ..."},
        {"nOFF\n3\n3 1 0\n", "m.off:1",
         "OFF variant 'nOFF' (4-D or n-D vertices) is not read; expected OFF, COFF, NOFF, "
         "CNOFF, STOFF, ..."},
        {"OFF BINARY\n", "m.off:1", "binary OFF is not read; write it as text"},
        {"OFF\n", "m.off:1", "the file ends before the vertex and face counts"},
        {"OFF\n3 one 0\n", "m.off:2", "expected the vertex and face counts, got '3 one'"},
        {"OFF\n3\n", "m.off:2", "expected the vertex and face counts, got '3'"},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n", "m.off:2",
         "declares 3 vertices and 1 faces, more than the file's 22 bytes can hold"},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n\n\n\n\n\n\n\n\n\n\n\n\n", "m.off:16",
         "the file ends after 2 of its 3 vertices (truncated?)"},
        {"OFF\n3 2 0\n" + triangle + "3 0 1 2\n\n\n\n\n", "m.off:10",
         "the file ends after 1 of its 2 faces (truncated?)"},
        {"OFF\n3 1 0\n0 0 0 1\n1 0 0\n0 1 0\n3 0 1 2\n", "m.off:3",
         "vertex 0: expected 3 numbers (x y z), got 4"},
        {"COFF\n3 1 0\n0 0 0 1 0\n1 0 0\n0 1 0\n3 0 1 2\n", "m.off:3",
         "vertex 0: expected 6 or 7 numbers (x y z r g b [a]), got 5"},
        {"COFF\n3 1 0\n0 0 0 1 -1 0\n1 0 0 1 1 1\n0 1 0 1 1 1\n3 0 1 2\n", "m.off:3",
         "vertex 0: the colour (r, g, b) must be finite and >= 0"},
        // A double beyond float's range (found by fuzz/mesh_fuzz.cpp: the colour was infinite).
        {"COFF\n3 1 0\n0 0 0 1 0 0\n1 0 0 0 0 2551e38\n0 1 0 1 1 1\n3 0 1 2\n", "m.off:4",
         "vertex 1: the colour (r, g, b) must be finite and >= 0"},
        {"OFF\n3 1 0\n0 0 0\n1 0 1e19\n0 1 0\n3 0 1 2\n", "m.off:4",
         "vertex 1: coordinates must be a finite number (in float range) of magnitude <= 1e18, "
         "so that its square fits a float"},
        {"OFF\n3 1 0\n" + triangle + "0 1 2\n", "m.off:6",
         "face 0: expected its vertex count (1 or more)"},
        {"OFF\n3 1 0\n" + triangle + "4097 0 1 2\n", "m.off:6",
         "face 0: " + polygon_vertex_limit_text(4097)},
        {"OFF\n3 1 0\n" + triangle + "3 0 1 x\n", "m.off:6",
         "face 0: vertex index 'x' is not an integer"},
        {"OFF\n3 1 0\n" + triangle + "3 0 1 -1\n", "m.off:6",
         "face 0: vertex index -1 out of range (the file has 3 vertices)"},
        {"OFF\n3 1 0\n" + triangle + "3 0 1 2 0 0\n", "m.off:6",
         "face 0: 2 numbers after its 3 vertex indices; a face colour has 1, 3 or 4"},
        {"OFF\n3 1 0\n" + triangle + "3 0 1 2 red\n", "m.off:6",
         "face 0: its colour 'red' is not a number"},
    };
    for (const Case& c : cases) {
        const InputError e = error_of(c.text);
        EXPECT_EQ(e.where(), c.where) << c.text;
        EXPECT_EQ(e.message(), c.message) << c.text;
    }
}

}  // namespace
}  // namespace rayo
