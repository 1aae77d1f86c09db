// Tests of TriangleMesh::add_convex_polygon (core/shapes/mesh.h): fan triangulation of NFF convex
// polygons, refusal of degenerate polygons, and vertex normals kept aligned with positions.
#include "core/shapes/mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace rayo {
namespace {

using Tri = std::array<uint32_t, 3>;

std::vector<Vec3> regular_polygon(int n, float z = 0.0f) {
    std::vector<Vec3> v;
    for (int i = 0; i < n; ++i) {
        const float a = 2.0f * kPi * float(i) / float(n);
        v.emplace_back(std::cos(a), std::sin(a), z);
    }
    return v;
}

TEST(Mesh, ConvexPolygonsBecomeFans) {
    TriangleMesh mesh;
    // A triangle: one triangle. A square: 2. A regular pentagon: 3. N − 2 each.
    ASSERT_TRUE(mesh.add_convex_polygon(regular_polygon(3), {}, 7));
    EXPECT_EQ(mesh.triangle_count(), 1u);
    ASSERT_TRUE(mesh.add_convex_polygon(
        {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)}, {}, 8));
    EXPECT_EQ(mesh.triangle_count(), 3u);
    ASSERT_TRUE(mesh.add_convex_polygon(regular_polygon(5, 2.0f), {}, 9));
    EXPECT_EQ(mesh.triangle_count(), 6u);

    // Positions appended in order, 3 + 4 + 5; no normals for flat polygons.
    ASSERT_EQ(mesh.positions.size(), 12u);
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_EQ(mesh.positions[3], Vec3(0, 0, 1));
    EXPECT_EQ(mesh.positions[6], Vec3(0, 1, 1));

    // The fan around each polygon's first vertex, in the polygon's winding.
    const std::vector<Tri> expected = {{0, 1, 2}, {3, 4, 5},  {3, 5, 6},
                                       {7, 8, 9}, {7, 9, 10}, {7, 10, 11}};
    ASSERT_EQ(mesh.triangles.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(mesh.triangles[i], expected[i]) << i;
    // One material per triangle.
    EXPECT_EQ(mesh.materials, (std::vector<uint32_t>{7, 8, 8, 9, 9, 9}));

    // The fan covers the polygon: the triangle areas sum to the square's area 1 and to the
    // regular pentagon's (5/2)·sin 72° = 2.377641.
    auto area = [&](size_t t) {
        const auto& tri = mesh.triangles[t];
        return 0.5f * glm::length(glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                             mesh.positions[tri[2]] - mesh.positions[tri[0]]));
    };
    EXPECT_NEAR(area(1) + area(2), 1.0f, 1e-6f);
    EXPECT_NEAR(area(3) + area(4) + area(5), 2.5f * std::sin(72.0f * kPi / 180.0f), 1e-5f);
    // Winding preserved: the counter-clockwise square (seen from +z) faces +z.
    const auto& t1 = mesh.triangles[1];
    const Vec3 ng = glm::cross(mesh.positions[t1[1]] - mesh.positions[t1[0]],
                               mesh.positions[t1[2]] - mesh.positions[t1[0]]);
    EXPECT_GT(ng.z, 0.0f);
}

TEST(Mesh, RejectsFewerThanThreeVertices) {
    TriangleMesh mesh;
    EXPECT_FALSE(mesh.add_convex_polygon({}, {}, 0));
    EXPECT_FALSE(mesh.add_convex_polygon({Vec3(0.0f)}, {}, 0));
    EXPECT_FALSE(mesh.add_convex_polygon({Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f)}, {}, 0));
    EXPECT_FALSE(mesh.add_convex_polygon({Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f)},
                                         {Vec3(0, 0, 1), Vec3(0, 0, 1)}, 0));
    // Nothing was added.
    EXPECT_TRUE(mesh.positions.empty());
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_TRUE(mesh.triangles.empty());
    EXPECT_TRUE(mesh.materials.empty());
}

TEST(Mesh, RejectsCollinearAndCoincidentPolygons) {
    TriangleMesh mesh;
    ASSERT_TRUE(mesh.add_convex_polygon(regular_polygon(3), {}, 0));
    const TriangleMesh before = mesh;
    // Three and four points on a line.
    EXPECT_FALSE(mesh.add_convex_polygon({Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)}, {}, 1));
    EXPECT_FALSE(mesh.add_convex_polygon(
        {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 0, 0), Vec3(-2, 0, 0)}, {}, 1));
    // All at one point.
    EXPECT_FALSE(mesh.add_convex_polygon({Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3)}, {}, 1));
    // NaN coordinates have no area either.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(mesh.add_convex_polygon({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, nan, 0)}, {}, 1));
    // The mesh is unchanged by the refusals.
    EXPECT_EQ(mesh.positions, before.positions);
    EXPECT_EQ(mesh.triangles, before.triangles);
    EXPECT_EQ(mesh.materials, before.materials);
    EXPECT_TRUE(mesh.normals.empty());
}

TEST(Mesh, DegenerateFanTrianglesAreSkipped) {
    // A square with a repeated corner: the fan triangle (v0, v1, v2) has zero area and is
    // dropped; the polygon still has area and keeps the two real triangles.
    TriangleMesh mesh;
    ASSERT_TRUE(mesh.add_convex_polygon(
        {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, {}, 4));
    EXPECT_EQ(mesh.positions.size(), 5u);
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[0], (Tri{0, 2, 3}));
    EXPECT_EQ(mesh.triangles[1], (Tri{0, 3, 4}));
    EXPECT_EQ(mesh.materials.size(), 2u);
}

TEST(Mesh, VertexNormalsStayAlignedWhenMixingFlatAndPatchPolygons) {
    TriangleMesh mesh;
    // Flat, patch (NFF `pp`), flat, patch: normals, when present, must be one per position, with
    // zero (= use the geometric normal) for the flat polygons' vertices.
    ASSERT_TRUE(mesh.add_convex_polygon({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {}, 0));
    EXPECT_TRUE(mesh.normals.empty());
    const std::vector<Vec3> patch = {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
    const std::vector<Vec3> patch_normals = {
        glm::normalize(Vec3(-1, -1, 1)), glm::normalize(Vec3(1, -1, 1)),
        glm::normalize(Vec3(1, 1, 1)), glm::normalize(Vec3(-1, 1, 1))};
    ASSERT_TRUE(mesh.add_convex_polygon(patch, patch_normals, 1));
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_TRUE(mesh.add_convex_polygon({Vec3(0, 0, 2), Vec3(1, 0, 2), Vec3(0, 1, 2)}, {}, 2));
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    const std::vector<Vec3> tri_normals = {Vec3(0, 0, 1), Vec3(0, 1, 0), Vec3(1, 0, 0)};
    ASSERT_TRUE(
        mesh.add_convex_polygon({Vec3(0, 0, 3), Vec3(1, 0, 3), Vec3(0, 1, 3)}, tri_normals, 3));
    ASSERT_EQ(mesh.positions.size(), 13u);  // 3 + 4 + 3 + 3
    ASSERT_EQ(mesh.normals.size(), 13u);
    for (int i : {0, 1, 2, 7, 8, 9}) EXPECT_EQ(mesh.normals[i], Vec3(0.0f)) << i;
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(mesh.positions[3 + i], patch[i]);
        EXPECT_EQ(mesh.normals[3 + i], patch_normals[i]) << i;
    }
    for (int i = 0; i < 3; ++i) EXPECT_EQ(mesh.normals[10 + i], tri_normals[i]) << i;
    // Every triangle corner of the patches reads the normal given with its position.
    ASSERT_EQ(mesh.triangles.size(), 5u);
    EXPECT_EQ(mesh.triangles[1], (Tri{3, 4, 5}));
    EXPECT_EQ(mesh.triangles[2], (Tri{3, 5, 6}));
    EXPECT_EQ(mesh.triangles[4], (Tri{10, 11, 12}));
    EXPECT_EQ(mesh.materials, (std::vector<uint32_t>{0, 1, 1, 2, 3}));
}

TEST(Mesh, RejectsNonFiniteVerticesAndMismatchedNormals) {
    TriangleMesh mesh;
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(mesh.add_convex_polygon({Vec3(0), Vec3(inf, 0, 0), Vec3(0, 1, 0)}, {}, 0));
    EXPECT_FALSE(mesh.add_convex_polygon({Vec3(0), Vec3(1, 0, 0), Vec3(0, NAN, 0)}, {}, 0));
    // Two normals for three vertices: refused rather than read past the end.
    EXPECT_FALSE(mesh.add_convex_polygon({Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0)},
                                         {Vec3(0, 0, 1), Vec3(0, 0, 1)}, 0));
    EXPECT_TRUE(mesh.positions.empty());
    EXPECT_TRUE(mesh.triangles.empty());
}

}  // namespace
}  // namespace rayo
