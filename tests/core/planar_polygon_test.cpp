// Tests of the point-in-polygon polygon (core/shapes/planar_polygon.h): the two fill rules on
// simple and self-intersecting outlines, agreement with the triangulation rayo renders (a
// concave gear like the SPD's), the plane hit, and the shape traced by Embree as user geometry.
#include "core/shapes/planar_polygon.h"

#include <embree3/rtcore.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/embree_device.h"
#include "core/shapes/polygon_triangulation.h"
#include "core/user_geometry.h"

namespace rayo {
namespace {

// A gear outline in the plane z = 0 like the SPD gears': `teeth` teeth of 4 vertices, half of
// them reflex.
std::vector<Vec3> gear(int teeth) {
    std::vector<Vec3> v;
    const double step = 2.0 * M_PI / teeth;
    const double corners[4][2] = {{0.0, 0.7}, {0.15, 1.0}, {0.35, 1.0}, {0.5, 0.7}};
    for (int t = 0; t < teeth; ++t) {
        for (const auto& c : corners) {
            const double a = t * step + c[0] * step;
            v.emplace_back(float(c[1] * std::cos(a)), float(c[1] * std::sin(a)), 0.0f);
        }
    }
    return v;
}

// The five points of a pentagram, drawn in one stroke: the centre pentagon is wound twice.
std::vector<Vec3> pentagram() {
    std::vector<Vec3> v;
    for (int k = 0; k < 5; ++k) {
        const double a = M_PI / 2 + k * 4.0 * M_PI / 5.0;
        v.emplace_back(float(std::cos(a)), float(std::sin(a)), 0.0f);
    }
    return v;
}

double distance_to_segment(double px, double py, const Vec3& a, const Vec3& b) {
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double s =
        std::clamp(((px - a.x) * ex + (py - a.y) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
    return std::hypot(px - (a.x + s * ex), py - (a.y + s * ey));
}

bool in_triangle(double px, double py, const Vec3& a, const Vec3& b, const Vec3& c) {
    const auto side = [&](const Vec3& p, const Vec3& q) {
        return (q.x - p.x) * (py - p.y) - (px - p.x) * (q.y - p.y);
    };
    const double s0 = side(a, b), s1 = side(b, c), s2 = side(c, a);
    return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

TEST(PlanarPolygon, SquareContainsItsInsideOnly) {
    const auto square =
        PlanarPolygon::make({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, FillRule::EvenOdd);
    ASSERT_TRUE(square);
    EXPECT_TRUE(square->contains(0.5f, 0.5f));
    EXPECT_TRUE(square->contains(0.01f, 0.99f));
    EXPECT_FALSE(square->contains(1.5f, 0.5f));
    EXPECT_FALSE(square->contains(-0.1f, 0.5f));
    EXPECT_FALSE(square->contains(0.5f, 1.1f));
}

TEST(PlanarPolygon, PentagramCentreIsOutsideByParityInsideByWinding) {
    const auto parity = PlanarPolygon::make(pentagram(), FillRule::EvenOdd);
    const auto winding = PlanarPolygon::make(pentagram(), FillRule::NonZeroWinding);
    ASSERT_TRUE(parity && winding);
    EXPECT_FALSE(parity->contains(0.0f, 0.0f));
    EXPECT_TRUE(winding->contains(0.0f, 0.0f));
    // A point of the star (between the centre pentagon and a tip) is inside by both rules.
    EXPECT_TRUE(parity->contains(0.0f, 0.7f));
    EXPECT_TRUE(winding->contains(0.0f, 0.7f));
    EXPECT_FALSE(parity->contains(0.9f, 0.9f));
    EXPECT_FALSE(winding->contains(0.9f, 0.9f));
}

// On a simple concave outline both rules cover exactly what the triangles rayo renders cover:
// a 401² grid over the gear, points within 1e-5 of the outline left out (either side is right).
TEST(PlanarPolygon, ConcaveGearAgreesWithItsTriangulation) {
    const std::vector<Vec3> outline = gear(36);
    const std::vector<PolygonTriangle> triangles = triangulate_polygon(outline);
    ASSERT_EQ(triangles.size(), outline.size() - 2);
    for (const FillRule rule : {FillRule::EvenOdd, FillRule::NonZeroWinding}) {
        const auto polygon = PlanarPolygon::make(outline, rule);
        ASSERT_TRUE(polygon);
        int inside = 0, compared = 0, disagreements = 0;
        for (int i = 0; i <= 400; ++i) {
            for (int j = 0; j <= 400; ++j) {
                const double x = -1.1 + 2.2 * i / 400.0, y = -1.1 + 2.2 * j / 400.0;
                double edge = std::numeric_limits<double>::infinity();
                for (size_t k = 0; k < outline.size(); ++k) {
                    edge = std::min(edge, distance_to_segment(x, y, outline[k],
                                                              outline[(k + 1) % outline.size()]));
                }
                if (edge < 1e-5) continue;
                bool covered = false;
                for (const PolygonTriangle& t : triangles) {
                    covered =
                        covered || in_triangle(x, y, outline[t[0]], outline[t[1]], outline[t[2]]);
                }
                ++compared;
                inside += covered;
                disagreements += covered != polygon->contains(float(x), float(y));
            }
        }
        EXPECT_EQ(disagreements, 0) << "of " << compared << " points";
        EXPECT_GT(inside, compared / 5);  // the grid really samples the gear
    }
}

TEST(PlanarPolygon, RayMeetsTheTiltedPlaneAtTheClosedFormDistance) {
    // A unit square in the plane x + z = 1 (normal (1, 0, 1)/√2), wound counter-clockwise seen
    // from that normal.
    const auto square =
        PlanarPolygon::make({{1, 0, 0}, {1, 1, 0}, {0, 1, 1}, {0, 0, 1}}, FillRule::EvenOdd);
    ASSERT_TRUE(square);
    EXPECT_NEAR(square->normal().x, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(square->normal().z, std::sqrt(0.5f), 1e-6f);
    ShapeHit hit;
    // From (0.5, 0.5, -3) along +z: the plane at z = 0.5, so t = 3.5.
    ASSERT_TRUE(square->nearest({0.5f, 0.5f, -3.0f}, {0, 0, 1}, 0.0f, 100.0f, hit));
    EXPECT_NEAR(hit.t, 3.5f, 1e-5f);
    EXPECT_FALSE(square->nearest({0.5f, 0.5f, -3.0f}, {0, 0, 1}, 0.0f, 3.0f, hit));    // tfar
    EXPECT_FALSE(square->nearest({0.5f, 1.5f, -3.0f}, {0, 0, 1}, 0.0f, 100.0f, hit));  // outside
    EXPECT_FALSE(square->nearest({0.5f, 0.5f, -3.0f}, {0, 1, 0}, 0.0f, 100.0f, hit));  // parallel
}

TEST(PlanarPolygon, DegenerateOutlinesAreRefused) {
    EXPECT_FALSE(PlanarPolygon::make({{0, 0, 0}, {1, 0, 0}}, FillRule::EvenOdd));
    EXPECT_FALSE(PlanarPolygon::make({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, FillRule::EvenOdd));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(PlanarPolygon::make({{0, 0, 0}, {1, 0, 0}, {0, nan, 0}}, FillRule::EvenOdd));
}

// Traced by Embree through the generic user-geometry callbacks: a ray through a tooth hits, a
// ray through the gap between two teeth misses (the fan triangulation used to cover it).
TEST(PlanarPolygon, EmbreeUserGeometryHitsTeethAndMissesGaps) {
    const std::vector<PlanarPolygon> polygons = {*PlanarPolygon::make(gear(36), FillRule::EvenOdd)};
    UserGeometryData<PlanarPolygon> data{polygons.data(), polygons.data()};
    RTCScene scene = rtcNewScene(embree_device());
    RTCGeometry geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, 1);
    rtcSetGeometryUserData(geometry, &data);
    rtcSetGeometryBoundsFunction(geometry, user_bounds<PlanarPolygon>, nullptr);
    rtcSetGeometryIntersectFunction(geometry, user_intersect<PlanarPolygon>);
    rtcSetGeometryOccludedFunction(geometry, user_occluded<PlanarPolygon>);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene);
    const auto trace = [&](double angle, double radius) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rayhit{};
        rayhit.ray.org_x = float(radius * std::cos(angle));
        rayhit.ray.org_y = float(radius * std::sin(angle));
        rayhit.ray.org_z = 2.0f;
        rayhit.ray.dir_z = -1.0f;
        rayhit.ray.tfar = 10.0f;
        rayhit.ray.mask = ~0u;
        rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rayhit);
        return rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID ? rayhit.ray.tfar : -1.0f;
    };
    const double step = 2.0 * M_PI / 36;
    EXPECT_NEAR(trace(0.25 * step, 0.85), 2.0f, 1e-5f);  // the middle of tooth 0
    EXPECT_EQ(trace(0.75 * step, 0.85), -1.0f);          // the gap after it
    EXPECT_NEAR(trace(0.75 * step, 0.5), 2.0f, 1e-5f);   // the hub
    rtcReleaseScene(scene);
}

}  // namespace
}  // namespace rayo
