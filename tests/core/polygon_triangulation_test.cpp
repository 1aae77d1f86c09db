// Tests of the polygon triangulation (core/shapes/polygon_triangulation.h) and
// TriangleMesh::add_polygon: concave outlines (L, star, comb, a gear like the SPD's) covered
// exactly once by triangles that keep the polygon's winding; convex polygons unchanged from the fan
// rayo always made.
#include "core/shapes/polygon_triangulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/shapes/mesh.h"

namespace rayo {
namespace {

using Tri = PolygonTriangle;

struct Point {
    double x, y;
};

// A 2D outline placed in 3D: origin + x·u + y·v (u, v orthonormal), so that the tests also cover
// tilted planes and coordinates far from the origin.
struct Frame {
    DVec3 origin{0.0}, u{1, 0, 0}, v{0, 1, 0};
    std::vector<Vec3> place(const std::vector<Point>& outline) const {
        std::vector<Vec3> out;
        for (const Point& p : outline) out.push_back(Vec3(origin + p.x * u + p.y * v));
        return out;
    }
};

Frame tilted_far_frame() {
    Frame f;
    f.origin = DVec3(1000.0, -250.0, 40.0);
    f.u = glm::normalize(DVec3(1.0, 2.0, 2.0));
    f.v = glm::normalize(glm::cross(DVec3(0.0, 0.0, 1.0), f.u));
    return f;
}

double cross2(const Point& a, const Point& b, const Point& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

double shoelace_area(const std::vector<Point>& outline) {  // signed, > 0 counter-clockwise
    double twice = 0.0;
    for (size_t i = 0; i < outline.size(); ++i) {
        const Point& a = outline[i];
        const Point& b = outline[(i + 1) % outline.size()];
        twice += a.x * b.y - a.y * b.x;
    }
    return 0.5 * twice;
}

bool inside_polygon(const std::vector<Point>& outline, const Point& p) {  // even-odd rule
    bool inside = false;
    for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        const Point &a = outline[i], &b = outline[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
            inside = !inside;
        }
    }
    return inside;
}

bool strictly_inside_triangle(const Point& a, const Point& b, const Point& c, const Point& p) {
    const double d1 = cross2(a, b, p), d2 = cross2(b, c, p), d3 = cross2(c, a, p);
    return (d1 > 0 && d2 > 0 && d3 > 0) || (d1 < 0 && d2 < 0 && d3 < 0);
}

// Samples a 101×101 grid over the outline's bounds (offset so that no sample lies on the integer
// coordinates the outlines use) and counts the samples that are not covered exactly once inside
// the outline, or are covered at all outside it.
int coverage_errors(const std::vector<Point>& outline, const std::vector<Tri>& triangles) {
    double x0 = outline[0].x, x1 = x0, y0 = outline[0].y, y1 = y0;
    for (const Point& p : outline) {
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    constexpr int kSamples = 101;
    int errors = 0;
    for (int j = 0; j < kSamples; ++j) {
        for (int i = 0; i < kSamples; ++i) {
            const Point p{x0 + (x1 - x0) * (i + 0.5137) / kSamples,
                          y0 + (y1 - y0) * (j + 0.4871) / kSamples};
            int covered = 0;
            for (const Tri& t : triangles) {
                covered += strictly_inside_triangle(outline[t[0]], outline[t[1]], outline[t[2]], p);
            }
            errors += covered != (inside_polygon(outline, p) ? 1 : 0);
        }
    }
    return errors;
}

std::vector<Tri> fan(size_t n) {
    std::vector<Tri> out;
    for (uint32_t i = 1; i + 1 < n; ++i) out.push_back({0, i, i + 1});
    return out;
}

// Everything a triangulation of a simple outline must satisfy, in any frame: N − 2 triangles of
// distinct in-range corners, each non-degenerate one wound like the polygon (its normal along
// the Newell normal), 3D areas adding up to the polygon's, and every sample covered once inside,
// never outside.
void expect_exact_triangulation(const std::vector<Point>& outline, const Frame& frame,
                                const std::string& name) {
    SCOPED_TRACE(name);
    const std::vector<Vec3> vertices = frame.place(outline);
    const std::vector<Tri> triangles = triangulate_polygon(vertices);
    ASSERT_EQ(triangles.size(), outline.size() - 2);
    const DVec3 newell = newell_normal(vertices);
    double area = 0.0;
    for (const Tri& t : triangles) {
        ASSERT_LT(t[0], outline.size());
        ASSERT_LT(t[1], outline.size());
        ASSERT_LT(t[2], outline.size());
        EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
        const DVec3 a(vertices[t[0]]), b(vertices[t[1]]), c(vertices[t[2]]);
        const DVec3 n = glm::cross(b - a, c - a);
        area += 0.5 * glm::length(n);
        // Winding: each triangle's 2D orientation agrees with the outline's.
        const double orientation = cross2(outline[t[0]], outline[t[1]], outline[t[2]]);
        if (std::abs(orientation) > 1e-9) {
            EXPECT_EQ(orientation > 0, shoelace_area(outline) > 0) << t[0] << " " << t[1];
            EXPECT_GT(glm::dot(n, newell), 0.0) << t[0] << " " << t[1] << " " << t[2];
        }
    }
    EXPECT_NEAR(area, std::abs(shoelace_area(outline)), 1e-4 * std::abs(shoelace_area(outline)));
    EXPECT_EQ(coverage_errors(outline, triangles), 0);
}

// An L whose first vertex sees neither arm's far end: the fan from it leaves the polygon.
const std::vector<Point> kL = {{2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}};

// A five-pointed star (10 vertices), starting at a tip.
std::vector<Point> star(int points = 5, double outer = 5.0, double inner = 2.0) {
    std::vector<Point> out;
    for (int i = 0; i < 2 * points; ++i) {
        const double r = i % 2 == 0 ? outer : inner;
        const double a = M_PI / 2 + M_PI * i / points;
        out.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return out;
}

// A comb: a bar along the bottom with four teeth pointing up, starting at the bottom-right
// corner (its first two edges, right side then the last tooth's top, form a convex angle).
const std::vector<Point> kComb = {{9, 0}, {9, 4}, {8, 4}, {8, 1}, {6, 1}, {6, 4}, {5, 4},
                                  {5, 1}, {3, 1}, {3, 4}, {2, 4}, {2, 1}, {0, 1}, {0, 0}};

// A gear outline like the SPD's gears: 36 teeth of 4 vertices each (144 vertices).
std::vector<Point> gear() {
    std::vector<Point> out;
    constexpr int kTeeth = 36;
    for (int t = 0; t < kTeeth; ++t) {
        const double a = 2.0 * M_PI * t / kTeeth, step = 2.0 * M_PI / kTeeth;
        const double corners[4][2] = {
            {0.0, 0.9}, {0.15 * step, 1.0}, {0.35 * step, 1.0}, {0.5 * step, 0.9}};
        for (const auto& c : corners) {
            out.push_back({c[1] * std::cos(a + c[0]), c[1] * std::sin(a + c[0])});
        }
    }
    return out;
}

TEST(PolygonTriangulation, ConcaveOutlinesAreCoveredExactlyOnce) {
    const Frame flat;
    const Frame tilted = tilted_far_frame();
    for (const Frame* frame : {&flat, &tilted}) {
        const std::string where = frame == &flat ? " (z = 0)" : " (tilted, far)";
        expect_exact_triangulation(kL, *frame, "L" + where);
        expect_exact_triangulation(star(), *frame, "star" + where);
        expect_exact_triangulation(star(12, 3.0, 2.5), *frame, "12-point star" + where);
        expect_exact_triangulation(kComb, *frame, "comb" + where);
        expect_exact_triangulation(gear(), *frame, "gear" + where);
    }
}

TEST(PolygonTriangulation, TheFanWouldBeWrongForTheseOutlines) {
    // Guards the test above: the checks do see a fan that leaves a concave outline.
    EXPECT_GT(coverage_errors(kL, fan(kL.size())), 0);
    EXPECT_GT(coverage_errors(star(), fan(10)), 0);
    EXPECT_GT(coverage_errors(kComb, fan(kComb.size())), 0);
    EXPECT_GT(coverage_errors(gear(), fan(144)), 0);
}

TEST(PolygonTriangulation, ClockwiseOutlinesKeepTheirWinding) {
    // The same outlines listed the other way round face the other way: every triangle too.
    for (std::vector<Point> outline : {kL, star(), kComb, gear()}) {
        std::reverse(outline.begin(), outline.end());
        ASSERT_LT(shoelace_area(outline), 0.0);
        expect_exact_triangulation(outline, Frame{}, "reversed");
        const std::vector<Vec3> vertices = Frame{}.place(outline);
        EXPECT_LT(newell_normal(vertices).z, 0.0);
    }
}

TEST(PolygonTriangulation, CollinearAndRepeatedVerticesInConcaveOutlines) {
    // An L with extra vertices in the middle of edges and one repeated corner: still N − 2
    // triangles (some of zero area), still an exact cover.
    const std::vector<Point> outline = {{2, 0}, {2, 0.5}, {2, 1}, {1.5, 1}, {1, 1}, {1, 1},
                                        {1, 2}, {0, 2},   {0, 1}, {0, 0},   {1, 0}};
    expect_exact_triangulation(outline, Frame{}, "L with collinear vertices");
    expect_exact_triangulation(outline, tilted_far_frame(), "tilted L with collinear vertices");
}

TEST(PolygonTriangulation, ConvexPolygonsGiveTheFan) {
    // The triangles rayo made for every polygon before concave ones were handled: images of
    // convex-only scenes stay the same.
    std::vector<Point> hexagon;
    for (int i = 0; i < 6; ++i) hexagon.push_back({std::cos(i * M_PI / 3), std::sin(i * M_PI / 3)});
    const std::vector<Point> square_with_midpoint = {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}};
    const std::vector<Point> clockwise_square = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    const std::vector<Point>* const outlines[] = {&hexagon, &square_with_midpoint,
                                                  &clockwise_square};
    for (const std::vector<Point>* outline : outlines) {
        for (const Frame& frame : {Frame{}, tilted_far_frame()}) {
            const std::vector<Vec3> vertices = frame.place(*outline);
            EXPECT_TRUE(is_convex_polygon(vertices));
            EXPECT_EQ(triangulate_polygon(vertices), fan(outline->size()));
        }
    }
}

TEST(PolygonTriangulation, ConvexityTest) {
    EXPECT_FALSE(is_convex_polygon(Frame{}.place(kL)));
    EXPECT_FALSE(is_convex_polygon(Frame{}.place(star())));
    EXPECT_FALSE(is_convex_polygon(Frame{}.place(gear())));
    // A pentagram turns left at every vertex but goes around twice.
    std::vector<Point> pentagram;
    for (int i = 0; i < 5; ++i) {
        pentagram.push_back({std::cos(i * 4 * M_PI / 5), std::sin(i * 4 * M_PI / 5)});
    }
    EXPECT_FALSE(is_convex_polygon(Frame{}.place(pentagram)));
    // A square with a zero-width spike out of its top edge.
    EXPECT_FALSE(
        is_convex_polygon(Frame{}.place({{0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, 3}, {1, 2}, {0, 2}})));
    EXPECT_TRUE(is_convex_polygon(Frame{}.place({{0, 0}, {1, 0}, {0, 1}})));
    EXPECT_FALSE(is_convex_polygon({Vec3(0), Vec3(1, 0, 0)}));
}

TEST(PolygonTriangulation, DegenerateInputGivesNoTriangles) {
    EXPECT_TRUE(triangulate_polygon({}).empty());
    EXPECT_TRUE(triangulate_polygon({Vec3(0), Vec3(1, 0, 0)}).empty());
    EXPECT_TRUE(triangulate_polygon({Vec3(0), Vec3(1, 1, 1), Vec3(3, 3, 3)}).empty());
    EXPECT_TRUE(triangulate_polygon({Vec3(2), Vec3(2), Vec3(2), Vec3(2)}).empty());
    EXPECT_EQ(newell_normal({Vec3(0), Vec3(1, 1, 1), Vec3(3, 3, 3)}), DVec3(0.0));
    // Newell's normal is twice the vector area: 2 for the unit square in z = 0.
    EXPECT_EQ(newell_normal({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}),
              DVec3(0, 0, 2));
}

TEST(PolygonTriangulation, SelfIntersectingOutlineStillEnds) {
    // Not a simple polygon (a bow tie, a pentagram): no exact cover is promised, but the
    // triangulation ends with N − 2 in-range triangles.
    const std::vector<Vec3> bow_tie = {Vec3(0, 0, 0), Vec3(2, 2, 0), Vec3(2, 0, 0), Vec3(0, 2, 0),
                                       Vec3(-1, 1, 0)};
    const std::vector<Tri> triangles = triangulate_polygon(bow_tie);
    EXPECT_EQ(triangles.size(), 3u);
    for (const Tri& t : triangles) {
        for (uint32_t i : t) EXPECT_LT(i, bow_tie.size());
    }
}

TEST(MeshAddPolygon, ConvexPolygonsMatchAddConvexPolygon) {
    TriangleMesh fan_mesh, mesh;
    const std::vector<std::vector<Vec3>> polygons = {
        {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)},
        {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)},
        Frame{}.place({{0, 0}, {0, 1}, {1, 1}, {1, 0}})};
    for (const auto& polygon : polygons) {
        ASSERT_TRUE(fan_mesh.add_convex_polygon(polygon, {}, 3));
        ASSERT_TRUE(mesh.add_polygon(polygon, {}, 3));
    }
    EXPECT_EQ(mesh.positions, fan_mesh.positions);
    EXPECT_EQ(mesh.triangles, fan_mesh.triangles);
    EXPECT_EQ(mesh.materials, fan_mesh.materials);
}

TEST(MeshAddPolygon, ConcavePatchKeepsNormalsAndOffsets) {
    TriangleMesh mesh;
    ASSERT_TRUE(mesh.add_polygon({Vec3(0, 0, 5), Vec3(1, 0, 5), Vec3(0, 1, 5)}, {}, 0));
    const std::vector<Vec3> l = Frame{}.place(kL);
    std::vector<Vec3> normals;
    for (size_t i = 0; i < l.size(); ++i) {
        normals.push_back(glm::normalize(Vec3(0.1f * float(i), 0.0f, 1.0f)));
    }
    ASSERT_TRUE(mesh.add_polygon(l, normals, 7));
    ASSERT_EQ(mesh.positions.size(), 3u + 6u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (size_t i = 0; i < 3; ++i) EXPECT_EQ(mesh.normals[i], Vec3(0.0f));  // flat: zero
    for (size_t i = 0; i < l.size(); ++i) {
        EXPECT_EQ(mesh.positions[3 + i], l[i]);
        EXPECT_EQ(mesh.normals[3 + i], normals[i]);  // each position keeps its own normal
    }
    ASSERT_EQ(mesh.triangles.size(), 1u + 4u);
    EXPECT_EQ(mesh.materials, (std::vector<uint32_t>{0, 7, 7, 7, 7}));
    // The L's triangles are the triangulation's, offset by the three earlier positions, and
    // face +z like the counter-clockwise L.
    const std::vector<Tri> expected = triangulate_polygon(l);
    for (size_t t = 0; t < expected.size(); ++t) {
        const Tri& got = mesh.triangles[1 + t];
        EXPECT_EQ(got, (Tri{expected[t][0] + 3, expected[t][1] + 3, expected[t][2] + 3}));
        const Vec3 n = glm::cross(mesh.positions[got[1]] - mesh.positions[got[0]],
                                  mesh.positions[got[2]] - mesh.positions[got[0]]);
        EXPECT_GT(n.z, 0.0f);
    }
}

TEST(MeshAddPolygon, RefusesWhatAddConvexPolygonRefuses) {
    TriangleMesh mesh;
    EXPECT_FALSE(mesh.add_polygon({Vec3(0), Vec3(1, 0, 0)}, {}, 0));
    EXPECT_FALSE(mesh.add_polygon({Vec3(0), Vec3(1, 1, 1), Vec3(2, 2, 2)}, {}, 0));
    EXPECT_FALSE(mesh.add_polygon({Vec3(0), Vec3(1, 0, 0), Vec3(0, NAN, 0)}, {}, 0));
    EXPECT_FALSE(mesh.add_polygon(Frame{}.place(kL), {Vec3(0, 0, 1)}, 0));  // one normal for six
    EXPECT_TRUE(mesh.positions.empty());
    EXPECT_TRUE(mesh.triangles.empty());
}

}  // namespace
}  // namespace rayo
