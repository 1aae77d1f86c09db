// Tests of the shapes' outlines (core/shapes/outline.h): the sphere's silhouette circle, the
// cone's rims and grazing generators, the disk's rim, the box's edges, mesh edges once, and the
// chord count that keeps curves within a quarter pixel.
#include "core/shapes/outline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "core/shapes/mesh.h"
#include "core/shapes/registry.h"

namespace rayo {
namespace {

constexpr double kPiD = 3.14159265358979323846;

Outline outline_from(const DVec3& eye, double pixel_angle = 1e-3) {
    return Outline(OutlineView{eye, pixel_angle});
}

// Every segment's end is the next one's start: a closed polyline.
void expect_closed_polyline(const Outline& out, size_t first, size_t count) {
    for (size_t i = 0; i < count; ++i) {
        const OutlineSegment& s = out.segments()[first + i];
        const OutlineSegment& next = out.segments()[first + (i + 1) % count];
        EXPECT_EQ(s.b, next.a) << "segment " << i;
    }
}

TEST(SphereOutline, SilhouettePointsAreWhereRaysFromTheEyeTouch) {
    const Sphere sphere{Vec3(1.0f, -0.5f, -2.0f), 0.75f, 0};
    const DVec3 eye(0.2, 0.4, 6.0), centre(sphere.center);
    Outline out = outline_from(eye);
    sphere.outline(out);
    ASSERT_GE(out.segments().size(), static_cast<size_t>(Outline::kMinChords));
    expect_closed_polyline(out, 0, out.segments().size());
    for (const OutlineSegment& s : out.segments()) {
        // On the sphere, and the ray from the eye is perpendicular to the radius there.
        EXPECT_NEAR(glm::length(s.a - centre), 0.75, 1e-9);
        EXPECT_NEAR(glm::dot(glm::normalize(s.a - eye), glm::normalize(s.a - centre)), 0.0, 1e-9);
    }
}

TEST(SphereOutline, EyeInsideHasNoSilhouette) {
    const Sphere sphere{Vec3(0.0f), 2.0f, 0};
    Outline out = outline_from(DVec3(0.5, 0.0, 0.0));
    sphere.outline(out);
    EXPECT_TRUE(out.segments().empty());
}

TEST(ConeOutline, CylinderSilhouetteLinesByHand) {
    // Cylinder along y, radius 1, from y = 0 to 2; eye at distance 2 from the axis on +z. The
    // grazing rays touch where cos θ = r/D = 1/2: x = ±sin 60°, z = cos 60° = 0.5.
    Cone cylinder;
    cylinder.base = Vec3(0, 0, 0);
    cylinder.apex = Vec3(0, 2, 0);
    cylinder.base_radius = cylinder.apex_radius = 1.0f;
    Outline out = outline_from(DVec3(0, 1, 2));
    cylinder.outline(out);
    const size_t n = out.segments().size();
    ASSERT_GE(n, 2 * Outline::kMinChords + 2u);
    std::set<std::tuple<long, long, long, long>> lines;
    const auto grid = [](double v) { return std::lround(v * 1e6); };
    for (size_t i = n - 2; i < n; ++i) {
        const OutlineSegment& s = out.segments()[i];
        EXPECT_NEAR(s.a.y, 0.0, 1e-12);
        EXPECT_NEAR(s.b.y, 2.0, 1e-12);
        EXPECT_NEAR(s.a.x, s.b.x, 1e-12);
        EXPECT_NEAR(s.a.z, 0.5, 1e-9);
        EXPECT_NEAR(std::abs(s.a.x), std::sqrt(3.0) / 2.0, 1e-9);
        lines.insert({grid(s.a.x), grid(s.a.z), grid(s.b.x), grid(s.b.z)});
    }
    EXPECT_EQ(lines.size(), 2u);  // one on each side
    // The rims: two closed circles of radius 1 at y = 0 and y = 2.
    const size_t rim = (n - 2) / 2;
    expect_closed_polyline(out, 0, rim);
    expect_closed_polyline(out, rim, rim);
    for (size_t i = 0; i < 2 * rim; ++i) {
        const DVec3 p = out.segments()[i].a;
        EXPECT_NEAR(std::hypot(p.x, p.z), 1.0, 1e-9);
        EXPECT_NEAR(p.y, i < rim ? 0.0 : 2.0, 1e-12);
    }
}

TEST(ConeOutline, GeneratorsGrazeTheConeForAnyEye) {
    Cone cone;
    cone.base = Vec3(0.5f, -1.0f, 0.25f);
    cone.apex = Vec3(1.0f, 1.5f, -0.5f);
    cone.base_radius = 1.2f;
    cone.apex_radius = 0.3f;
    const ConeFrame f = make_cone_frame(cone);
    for (const DVec3 eye : {DVec3(0, 0, 8), DVec3(-6, 3, 1), DVec3(4, -5, -3)}) {
        Outline out = outline_from(eye);
        cone.outline(out);
        const size_t n = out.segments().size();
        for (size_t i = n - 2; i < n; ++i) {
            const OutlineSegment& s = out.segments()[i];
            // Along the generator the normal is e − slope·a, e the radial unit vector.
            const DVec3 e =
                glm::normalize((s.a - f.base) - glm::dot(s.a - f.base, f.axis) * f.axis);
            const DVec3 normal = glm::normalize(e - f.slope * f.axis);
            for (const double t : {0.0, 0.5, 1.0}) {
                const DVec3 p = s.a + t * (s.b - s.a);
                EXPECT_NEAR(glm::dot(normal, glm::normalize(p - eye)), 0.0, 1e-9);
            }
        }
    }
}

TEST(ConeOutline, EyeOnTheAxisSeesOnlyTheRims) {
    Cone cone;
    cone.base = Vec3(0, 0, 0);
    cone.apex = Vec3(0, 1, 0);
    cone.base_radius = 1.0f;
    cone.apex_radius = 0.0f;  // a point: no apex rim
    Outline out = outline_from(DVec3(0, 5, 0));
    cone.outline(out);
    expect_closed_polyline(out, 0, out.segments().size());
    for (const OutlineSegment& s : out.segments()) EXPECT_NEAR(s.a.y, 0.0, 1e-12);
}

TEST(DiskOutline, TheRimInTheDisksPlane) {
    Disk disk;
    disk.center = Vec3(1, 2, 3);
    disk.normal = glm::normalize(Vec3(1, 1, 0));
    disk.radius = 0.5f;
    Outline out = outline_from(DVec3(0, 0, 10));
    disk.outline(out);
    expect_closed_polyline(out, 0, out.segments().size());
    for (const OutlineSegment& s : out.segments()) {
        EXPECT_NEAR(glm::length(s.a - DVec3(disk.center)), 0.5, 1e-6);
        EXPECT_NEAR(glm::dot(s.a - DVec3(disk.center), DVec3(disk.normal)), 0.0, 1e-6);
    }
}

TEST(BoxOutline, TwelveAxisAlignedEdges) {
    const Box box{Vec3(-1, 0, 2), Vec3(3, 1, 4), 0};
    Outline out = outline_from(DVec3(0, 0, 10));
    box.outline(out);
    ASSERT_EQ(out.segments().size(), 12u);
    std::map<std::tuple<double, double, double>, int> corners;
    for (const OutlineSegment& s : out.segments()) {
        const DVec3 d = glm::abs(s.b - s.a);
        EXPECT_EQ((d.x > 0) + (d.y > 0) + (d.z > 0), 1);  // along one axis
        EXPECT_TRUE(d.x == 4.0 || d.y == 1.0 || d.z == 2.0);
        ++corners[{s.a.x, s.a.y, s.a.z}];
        ++corners[{s.b.x, s.b.y, s.b.z}];
    }
    EXPECT_EQ(corners.size(), 8u);
    for (const auto& [corner, edges] : corners) EXPECT_EQ(edges, 3);
}

TEST(MeshOutline, TetrahedronHasSixEdges) {
    TriangleMesh mesh;
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    Outline out = outline_from(DVec3(5, 5, 5));
    mesh.outline(out);
    EXPECT_EQ(out.segments().size(), 6u);
}

// How many segments outline the unit square [0,1]² in z = 0 and a second unit square beside it,
// from (1, 0, 0) and (1, 1, 0) to x = 2 at height `far_z`, each added as its own polygon (its
// own corners, two triangles).
size_t two_squares_segments(float far_z) {
    TriangleMesh mesh;
    EXPECT_TRUE(
        mesh.add_polygon({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, {}, 0));
    EXPECT_TRUE(mesh.add_polygon(
        {Vec3(1, 0, 0), Vec3(2, 0, far_z), Vec3(2, 1, far_z), Vec3(1, 1, 0)}, {}, 0));
    Outline out = outline_from(DVec3(0, 0, 10));
    mesh.outline(out);
    return out.segments().size();
}

TEST(MeshOutline, PolygonsSharingAnEdgeByPositionDrawItOnceAndSkipFlatDiagonals) {
    // Flat: the 2×1 rectangle's six unit edges; the shared edge and the diagonals lie inside
    // the flat face.
    EXPECT_EQ(two_squares_segments(0.0f), 6u);
    // Folded along the shared edge: that edge is drawn (once), the diagonals still are not.
    EXPECT_EQ(two_squares_segments(1.0f), 7u);
}

TEST(OutlineCircle, ChordsStayWithinAQuarterPixel) {
    // Sagitta R(1 − cos(π/N)) in pixels, for circles from tiny to filling the view.
    const double pixel_angle = 1e-3;
    Outline out = outline_from(DVec3(0), pixel_angle);
    for (const double radius : {1e-4, 0.01, 0.3, 1.0, 1.9}) {
        const double distance = 2.0;
        const int chords = out.circle_chords(radius, distance);
        const double radius_px = radius / (distance * pixel_angle);
        EXPECT_GE(chords, Outline::kMinChords);
        EXPECT_LE(radius_px * (1.0 - std::cos(kPiD / chords)), Outline::kMaxSagittaPixels + 1e-12)
            << radius;
        // And not wastefully many: one chord fewer would exceed the budget.
        if (chords > Outline::kMinChords) {
            EXPECT_GT(radius_px * (1.0 - std::cos(kPiD / (chords - 1))),
                      Outline::kMaxSagittaPixels);
        }
    }
}

TEST(Outline, EveryRegisteredShapeHasOne) {
    // One shape of each registered type with its default fields, in front of the eye: each
    // draws something (a new shape without outline() does not compile in draw_wireframe).
    Shapes shapes;
    shapes.for_each([](auto& v) { v.emplace_back(); });
    shapes.of<Csg>().front().add_leaf(Sphere{});  // a CSG is built, its default is empty
    shapes.for_each([](const auto& v) {
        Outline out = outline_from(DVec3(0.3, 0.4, 6.0));
        v.front().outline(out);
        EXPECT_GE(out.segments().size(), 4u) << ShapeOf<decltype(v)>::kName;
    });
}

}  // namespace
}  // namespace rayo
