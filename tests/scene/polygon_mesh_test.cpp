// Tests of the polygons the PLY, STL and OFF readers give becoming triangles
// (apps/scene/polygon_mesh.h): triangles as they are, larger faces triangulated convex or
// concave, points and lines dropped, the vertices' attributes kept.
#include "apps/scene/polygon_mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec3;

TEST(PolygonMesh, FacesBecomeTrianglesPointsAndLinesAreDropped) {
    PolygonMesh polygons;
    // An L of six vertices in z = 0 (concave at (1, 1)), then a point, a line and a triangle.
    polygons.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    polygons.colors.assign(6, Vec3(0.5f));
    polygons.corners = {0, 1, 2, 3, 4, 5};
    polygons.end_face();
    polygons.corners.push_back(3);
    polygons.end_face();
    polygons.corners.insert(polygons.corners.end(), {0, 1});
    polygons.end_face();
    polygons.corners.insert(polygons.corners.end(), {5, 4, 3});
    polygons.end_face();
    const TriangleMesh mesh = triangulate_polygon_mesh(std::move(polygons), 7);
    ASSERT_EQ(mesh.triangles.size(), 5u);  // 6 - 2, then the triangle
    EXPECT_EQ(mesh.materials, std::vector<uint32_t>(5, 7u));
    EXPECT_EQ(mesh.triangles.back(), (std::array<uint32_t, 3>{5, 4, 3}));
    EXPECT_EQ(mesh.positions.size(), 6u);
    EXPECT_EQ(mesh.colors.size(), 6u);
    EXPECT_TRUE(mesh.normals.empty());
    // The L's triangles cover its area (3) and each faces +z, as the L is wound.
    double area = 0.0;
    for (size_t t = 0; t < 4; ++t) {
        const auto& tri = mesh.triangles[t];
        const Vec3 n = glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                  mesh.positions[tri[2]] - mesh.positions[tri[0]]);
        EXPECT_GT(n.z, 0.0f) << t;
        area += 0.5 * n.z;
    }
    EXPECT_NEAR(area, 3.0, 1e-6);
}

TEST(PolygonMesh, UnitNormalOrZero) {
    expect_vec3(unit_normal_or_zero(Vec3(0, 3, 4)), 0, 0.6, 0.8);
    expect_vec3(unit_normal_or_zero(Vec3(0)), 0, 0, 0);
    expect_vec3(unit_normal_or_zero(Vec3(1, NAN, 0)), 0, 0, 0);
    expect_vec3(unit_normal_or_zero(Vec3(1e30f, 1e30f, 0)), 0, 0, 0);  // length overflows
}

}  // namespace
}  // namespace rayo
