// Tessellation of the analytic shapes (core/shapes/tessellation.h): every registered shape's
// pieces lie on its surface with its outward normal (checked against the shape's own
// intersection), locate() inverts the pieces, the triangles face outward, and the cell count
// follows max_edge.
#include "core/shapes/tessellation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/shapes/registry.h"

namespace rayo {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

template <typename S>
bool shape_nearest(const S& shape, const Vec3& origin, const Vec3& direction, ShapeHit& hit) {
    if constexpr (ShapeTraits<S>::kSelfIntersecting) {
        return shape.nearest(origin, direction, 0.0f, kInf, hit);
    } else {
        return shape.intersector().nearest(origin, direction, 0.0f, kInf, hit);
    }
}

// One of each tessellated shape, tilted and off the origin where the shape allows it.
Shapes sample_shapes() {
    Shapes shapes;
    shapes.of<Sphere>().push_back({Vec3(1, 2, 3), 1.5f, 0});
    Disk disk;
    disk.center = Vec3(-1, 0.5f, 2);
    disk.normal = glm::normalize(Vec3(1, 2, -0.5f));
    disk.radius = 0.8f;
    shapes.of<Disk>().push_back(disk);
    shapes.of<Box>().push_back({Vec3(-1, 0, 0.5f), Vec3(0.5f, 2, 1), 0});
    Cone cone;
    cone.base = Vec3(0, 0, 0);
    cone.apex = Vec3(0.5f, 2, 0.3f);
    cone.base_radius = 1.0f;
    cone.apex_radius = 0.25f;
    shapes.of<Cone>().push_back(cone);
    Ellipsoid ellipsoid;
    ellipsoid.center = Vec3(2, 0, -1);
    ellipsoid.radii = Vec3(1.0f, 2.0f, 0.5f);
    shapes.of<Ellipsoid>().push_back(ellipsoid);
    Cylinder cylinder;
    cylinder.base = Vec3(0, 1, 0);
    cylinder.top = Vec3(1, 2.5f, 0.5f);
    cylinder.radius = 0.6f;
    shapes.of<Cylinder>().push_back(cylinder);
    Paraboloid paraboloid;
    paraboloid.vertex = Vec3(1, -1, 0);
    paraboloid.axis = glm::normalize(Vec3(0.2f, 1, 0.4f));
    paraboloid.radius = 1.0f;
    paraboloid.height = 1.5f;
    shapes.of<Paraboloid>().push_back(paraboloid);
    Hyperboloid one, two;
    one.center = Vec3(-2, 1, 0);
    one.axis = glm::normalize(Vec3(1, 1, 0));
    one.radius = 0.5f;
    one.semi_axis = 0.7f;
    one.height = 2.0f;
    two = one;
    two.sheets = 2;
    two.semi_axis = 0.4f;
    shapes.of<Hyperboloid>().push_back(one);
    shapes.of<Hyperboloid>().push_back(two);
    return shapes;
}

// f(shape name, shape, pieces) for every sample shape.
template <typename F>
void for_each_sample(F&& f) {
    const Shapes shapes = sample_shapes();
    shapes.for_each([&](const auto& vector) {
        for (const auto& shape : vector) {
            SurfacePieces pieces;
            shape.pieces(pieces);
            f(std::string(ShapeOf<decltype(vector)>::kName), shape, pieces);
        }
    });
}

TEST(Tessellation, EveryShapeButTheGeneralQuadricHasPieces) {
    int shapes = 0;
    for_each_sample([&](const std::string& name, const auto&, const SurfacePieces& pieces) {
        EXPECT_FALSE(pieces.empty()) << name;
        ++shapes;
    });
    EXPECT_EQ(shapes, 9);
    SurfacePieces none;
    Quadric().pieces(none);
    EXPECT_TRUE(none.empty());
}

TEST(Tessellation, CellCentresLieOnTheSurfaceWithTheOutwardNormal) {
    // From just outside each cell's centre along the piece's normal, back toward the surface:
    // the shape's own intersection meets it there, with the same outward normal.
    for_each_sample([&](const std::string& name, const auto& shape, const SurfacePieces& pieces) {
        TessellationOptions options;
        options.max_edge = 0.3f;
        TessellatedMesh mesh;
        tessellate(pieces, options, mesh);
        for (size_t p = 0; p < pieces.size(); ++p) {
            const PieceGrid& grid = mesh.grids[p];
            for (uint32_t j = 0; j < grid.nv; ++j) {
                for (uint32_t i = 0; i < grid.nu; ++i) {
                    const double s = (i + 0.5) / grid.nu, t = (j + 0.5) / grid.nv;
                    const Vec3 point(pieces[p].point(s, t));
                    const Vec3 normal(pieces[p].normal(s, t));
                    ASSERT_NEAR(glm::length(normal), 1.0f, 1e-5f) << name;
                    constexpr float kAway = 1e-2f;
                    ShapeHit hit;
                    ASSERT_TRUE(shape_nearest(shape, point + kAway * normal, -normal, hit))
                        << name << " piece " << p << " s " << s << " t " << t;
                    EXPECT_NEAR(hit.t, kAway, 2e-5f) << name << " piece " << p;
                    EXPECT_GT(glm::dot(glm::normalize(hit.normal), normal), 0.9999f)
                        << name << " piece " << p << " s " << s << " t " << t;
                }
            }
        }
    });
}

TEST(Tessellation, LocateInvertsThePieces) {
    for_each_sample([&](const std::string& name, const auto&, const SurfacePieces& pieces) {
        for (uint32_t p = 0; p < pieces.size(); ++p) {
            for (double s : {0.1, 0.37, 0.8}) {
                for (double t : {0.05, 0.5, 0.93}) {
                    PiecePoint where;
                    ASSERT_TRUE(locate(pieces, Vec3(pieces[p].point(s, t)), where));
                    EXPECT_EQ(where.piece, p) << name;
                    EXPECT_NEAR(where.s, s, 1e-5) << name << " piece " << p;
                    EXPECT_NEAR(where.t, t, 1e-5) << name << " piece " << p;
                }
            }
        }
    });
}

TEST(Tessellation, TrianglesFaceOutwardAndCellsFollowMaxEdge) {
    for_each_sample([&](const std::string& name, const auto&, const SurfacePieces& pieces) {
        TessellationOptions options;
        options.max_edge = 0.25f;
        TessellatedMesh mesh;
        tessellate(pieces, options, mesh);
        ASSERT_FALSE(mesh.triangles.empty()) << name;
        for (const auto& tri : mesh.triangles) {
            const Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]],
                       c = mesh.positions[tri[2]];
            const Vec3 normals = mesh.normals[tri[0]] + mesh.normals[tri[1]] + mesh.normals[tri[2]];
            EXPECT_GT(glm::dot(glm::cross(b - a, c - a), normals), 0.0f) << name;
            // Two sides of every triangle are cell sides (the third is the cell's diagonal).
            float edges[3] = {glm::length(b - a), glm::length(c - b), glm::length(a - c)};
            std::sort(edges, edges + 3);
            EXPECT_LE(edges[1], 0.25f * 1.01f) << name;
        }
    });
}

TEST(Tessellation, SphereCountsAndArea) {
    SurfacePieces pieces;
    Sphere{Vec3(0.0f), 1.0f, 0}.pieces(pieces);
    auto tessellated = [&](float max_edge) {
        TessellationOptions options;
        options.max_edge = max_edge;
        TessellatedMesh mesh;
        tessellate(pieces, options, mesh);
        return mesh;
    };
    // No limit: 16 cells around, 8 along; the cells at the poles keep one triangle each.
    EXPECT_EQ(tessellated(0.0f).triangles.size(), 2u * 16u * 8u - 2u * 16u);
    // 2π/0.25 → 26 around, π/0.25 → 13 along.
    const TessellatedMesh mesh = tessellated(0.25f);
    EXPECT_EQ(mesh.grids[0].nu, 26u);
    EXPECT_EQ(mesh.grids[0].nv, 13u);
    EXPECT_EQ(mesh.triangles.size(), 2u * 26u * 13u - 2u * 26u);
    double area = 0.0;
    for (const auto& tri : mesh.triangles) {
        area += 0.5 * glm::length(glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                             mesh.positions[tri[2]] - mesh.positions[tri[0]]));
    }
    EXPECT_NEAR(area, 4.0 * M_PI, 0.02 * 4.0 * M_PI);
    // Every vertex on the unit sphere.
    for (const Vec3& v : mesh.positions) EXPECT_NEAR(glm::length(v), 1.0f, 1e-6f);
    // Halving the edge about quadruples the triangles.
    const double ratio = static_cast<double>(tessellated(0.125f).triangles.size()) /
                         static_cast<double>(mesh.triangles.size());
    EXPECT_GT(ratio, 3.5);
    EXPECT_LT(ratio, 4.5);
}

TEST(Tessellation, ChordErrorStaysWithinItsBudget) {
    // A circle of radius r cut into n chords deviates r·(1 − cos(π/n)) from them: a sphere of
    // radius 1 within 1e-3 needs n ≥ π/acos(1 − 1e-3) ≈ 70.2 around; half the budget per
    // direction asks √2 times that (99), the ceiling a little more. A cylinder's side is
    // straight along its axis: one cell that way.
    SurfacePieces sphere;
    Sphere{Vec3(0.0f), 1.0f, 0}.pieces(sphere);
    TessellationOptions options;
    options.max_chord = 1e-3f;
    TessellatedMesh mesh;
    tessellate(sphere, options, mesh);
    const double least = M_PI / std::acos(1.0 - 1e-3);
    EXPECT_GE(mesh.grids[0].nu, least);
    EXPECT_LE(mesh.grids[0].nu, 1.6 * least);
    for (const float bulge : mesh.bulge) EXPECT_LE(bulge, 1e-3f);
    EXPECT_GT(*std::max_element(mesh.bulge.begin(), mesh.bulge.end()), 0.25e-3f);

    Cylinder cylinder;
    cylinder.radius = 2.0f;
    cylinder.capped = false;
    SurfacePieces side;
    cylinder.pieces(side);
    tessellate(side, options, mesh);
    EXPECT_EQ(mesh.grids[0].nv, 1u);
    EXPECT_GE(mesh.grids[0].nu, M_PI / std::acos(1.0 - 1e-3 / 2.0));
    for (const float bulge : mesh.bulge) EXPECT_LE(bulge, 1e-3f);
}

TEST(Tessellation, CellPointInterpolatesWithinTheTriangleHoldingThePoint) {
    SurfacePieces pieces;
    Box{Vec3(0.0f), Vec3(1.0f), 0}.pieces(pieces);
    TessellationOptions options;
    options.max_edge = 0.5f;
    TessellatedMesh mesh;
    tessellate(pieces, options, mesh);
    ASSERT_EQ(mesh.triangles.size(), 6u * 8u);
    // The weighted corners give back the point, and the triangle has those corners.
    for (const Vec3& p :
         {Vec3(0.3f, 0.0f, 0.1f), Vec3(1.0f, 0.7f, 0.45f), Vec3(0.9f, 0.2f, 1.0f)}) {
        PiecePoint where;
        ASSERT_TRUE(locate(pieces, p, where));
        const CellPoint cell = cell_point(mesh, where);
        ASSERT_NE(cell.triangle, TessellatedMesh::kNoTriangle);
        Vec3 back(0.0f);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(cell.weights[c], 0.0f);
            back += cell.weights[c] * mesh.positions[cell.vertices[c]];
            const auto& tri = mesh.triangles[cell.triangle];
            EXPECT_NE(std::find(tri.begin(), tri.end(), cell.vertices[c]), tri.end());
        }
        EXPECT_NEAR(back.x, p.x, 1e-5f);
        EXPECT_NEAR(back.y, p.y, 1e-5f);
        EXPECT_NEAR(back.z, p.z, 1e-5f);
    }
}

}  // namespace
}  // namespace rayo
