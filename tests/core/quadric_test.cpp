// The quadric shapes (core/shapes/quadric.h, core/shapes/quadric_forms.h, through
// core/shapes/clipped_quadric.h): hits and normals against closed forms, crossings of the solid
// clipped to its box (caps, two inside intervals, open surfaces), rays starting inside, grazing
// rays, far origins, the fields' problems, and a quadric through the accel.
#include "core/shapes/quadric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/accel.h"
#include "core/shapes/quadric_forms.h"

namespace rayo {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// x² + y² + z² − 1 (the unit sphere) clipped to [−2, 2]³ unless told otherwise.
Quadric unit_sphere_quadric(const Vec3& lower = Vec3(-2.0f), const Vec3& upper = Vec3(2.0f)) {
    Quadric q;
    q.coefficients = {1, 1, 1, 0, 0, 0, 0, 0, 0, -1};
    q.clip = {lower, upper};
    return q;
}

Vec3 unit(const Vec3& v) {
    return glm::normalize(v);
}

void expect_direction(const Vec3& actual, const Vec3& expected, float tolerance = 1e-5f) {
    const Vec3 a = unit(actual), e = unit(expected);
    EXPECT_NEAR(a.x, e.x, tolerance);
    EXPECT_NEAR(a.y, e.y, tolerance);
    EXPECT_NEAR(a.z, e.z, tolerance);
}

TEST(Quadric, SphereHitsAtTheClosedFormDistanceWithTheRadialNormal) {
    const Quadric q = unit_sphere_quadric();
    ShapeHit hit;
    // From (0.6, 0, −5) along +z: enters at z = −√(1 − 0.36) = −0.8, t = 4.2; normal = p.
    ASSERT_TRUE(q.nearest(Vec3(0.6f, 0.0f, -5.0f), Vec3(0, 0, 1), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 4.2f);
    expect_direction(hit.normal, Vec3(0.6f, 0.0f, -0.8f));
    // Slanted, through the centre: t = 5 − 1.
    const Vec3 d = unit(Vec3(3.0f, 0.0f, 4.0f));
    ASSERT_TRUE(q.nearest(-5.0f * d, d, 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 4.0f, 1e-5f);
    expect_direction(hit.normal, -d);
}

TEST(Quadric, GeneralCoefficientsInTheIssueOrder) {
    // (x − 1)² + 4·(y − z)² ... written out: x² + 4y² + 4z² − 8yz − 2x + 1 − 1 = 0, i.e.
    // A = 1, B = 4, C = 4, F = −8, G = −2, J = 0: the elliptic cylinder (x−1)² + 4(y−z)² = 1.
    Quadric q;
    q.coefficients = {1, 4, 4, 0, 0, -8, -2, 0, 0, 0};
    q.clip = {Vec3(-3.0f), Vec3(3.0f)};
    ShapeHit hit;
    // Along x at y = z = 0: (x − 1)² = 1, roots x = 0 and x = 2; from x = −2: t = 2.
    ASSERT_TRUE(q.nearest(Vec3(-2.0f, 0.0f, 0.0f), Vec3(1, 0, 0), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 2.0f);
    expect_direction(hit.normal, Vec3(-1, 0, 0));
    // Along y at x = 1, z = 0.25: 4(y − 0.25)² = 1, y = −0.25 first; ∇q = (0, 8(y−z), −8(y−z)).
    ASSERT_TRUE(q.nearest(Vec3(1.0f, -2.0f, 0.25f), Vec3(0, 1, 0), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 1.75f);
    expect_direction(hit.normal, Vec3(0, -1, 1));
}

TEST(Quadric, FromInsideHitsTheFarSideWithTheOutwardNormal) {
    const Quadric q = unit_sphere_quadric();
    ShapeHit hit;
    ASSERT_TRUE(q.nearest(Vec3(0.0f, 0.5f, 0.0f), Vec3(0, 1, 0), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 0.5f);
    expect_direction(hit.normal, Vec3(0, 1, 0));
    SurfaceHit surface;
    Ray ray;
    ray.origin = Vec3(0.0f, 0.5f, 0.0f);
    ray.direction = Vec3(0, 1, 0);
    q.surface(ray, hit, surface);
    EXPECT_FLOAT_EQ(surface.position.y, 1.0f);
    EXPECT_EQ(surface.geometric_normal, Vec3(0, 1, 0));
    EXPECT_EQ(surface.object_size, 4.0f);
}

TEST(Quadric, ClippedSolidIsCappedByTheBoxFaces) {
    // The unit sphere cut to |z| <= 0.5: along the z axis the solid is [−0.5, 0.5], bounded by
    // the box faces (caps, normals ∓z); off the caps the sphere's own crossings remain.
    Quadric q = unit_sphere_quadric(Vec3(-2.0f, -2.0f, -0.5f), Vec3(2.0f, 2.0f, 0.5f));
    ShapeCrossing c[kMaxShapeCrossings];
    ASSERT_EQ(q.crossings(Vec3(0.0f, 0.0f, -5.0f), Vec3(0, 0, 1), c), 2);
    EXPECT_FLOAT_EQ(c[0].t, 4.5f);
    EXPECT_TRUE(c[0].entering);
    EXPECT_FLOAT_EQ(c[1].t, 5.5f);
    EXPECT_FALSE(c[1].entering);
    ShapeHit hit;
    ASSERT_TRUE(q.nearest(Vec3(0.0f, 0.0f, -5.0f), Vec3(0, 0, 1), 0.0f, kInf, hit));
    EXPECT_EQ(glm::normalize(hit.normal), Vec3(0, 0, -1));
    // At x = 0.9 the sphere spans |z| <= √0.19 < 0.5: no cap.
    ASSERT_TRUE(q.nearest(Vec3(0.9f, 0.0f, -5.0f), Vec3(0, 0, 1), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 5.0f - std::sqrt(0.19f), 1e-5f);
    // Open: the caps are no surface, so the axis ray passes through.
    q.capped = false;
    EXPECT_EQ(q.crossings(Vec3(0.0f, 0.0f, -5.0f), Vec3(0, 0, 1), c), 0);
    ASSERT_EQ(q.crossings(Vec3(0.9f, 0.0f, -5.0f), Vec3(0, 0, 1), c), 2);
    EXPECT_TRUE(c[0].entering);
    EXPECT_FALSE(c[1].entering);
}

TEST(Quadric, HyperboloidAlongItsAxisHasFourCrossings) {
    // Two sheets z² − x² − y² = 1, i.e. q = x² + y² − z² + 1 <= 0, in |z| <= 3: along the axis
    // the solid is [−3, −1] ∪ [1, 3]: four crossings, the outer two on the caps.
    Quadric q;
    q.coefficients = {1, 1, -1, 0, 0, 0, 0, 0, 0, 1};
    q.clip = {Vec3(-4.0f, -4.0f, -3.0f), Vec3(4.0f, 4.0f, 3.0f)};
    ShapeCrossing c[kMaxShapeCrossings];
    ASSERT_EQ(q.crossings(Vec3(0.0f, 0.0f, -10.0f), Vec3(0, 0, 1), c), 4);
    const float expected[] = {7.0f, 9.0f, 11.0f, 13.0f};
    for (int i = 0; i < 4; ++i) {
        EXPECT_FLOAT_EQ(c[i].t, expected[i]) << i;
        EXPECT_EQ(c[i].entering, i % 2 == 0) << i;
    }
    // From between the sheets the first hit is the upper vertex, normal −z (toward q > 0).
    ShapeHit hit;
    ASSERT_TRUE(q.nearest(Vec3(0.0f), Vec3(0, 0, 1), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 1.0f);
    expect_direction(hit.normal, Vec3(0, 0, -1));
}

TEST(Quadric, GrazingRaysHitInsideTheSilhouetteAndMissOutside) {
    const Quadric q = unit_sphere_quadric();
    ShapeHit hit;
    for (const float k : {1e-3f, 1e-4f}) {
        const float inside = 1.0f - k, outside = 1.0f + k;
        ASSERT_TRUE(q.nearest(Vec3(inside, 0.0f, -5.0f), Vec3(0, 0, 1), 0.0f, kInf, hit)) << k;
        const double closed = 5.0 - std::sqrt(1.0 - double(inside) * inside);
        EXPECT_NEAR(hit.t, closed, 1e-5) << k;
        EXPECT_FALSE(q.nearest(Vec3(outside, 0.0f, -5.0f), Vec3(0, 0, 1), 0.0f, kInf, hit)) << k;
    }
}

TEST(Quadric, FarOriginsKeepTheRelativeError) {
    // A unit sphere 1e5 away: the solve about the box's middle avoids |o|² − 1 cancelling.
    const Quadric q = unit_sphere_quadric();
    const Vec3 d = unit(Vec3(1.0f, 2.0f, -2.0f));
    ShapeHit hit;
    ASSERT_TRUE(q.nearest(-1e5f * d + Vec3(0.0f, 0.0f, 0.0f), d, 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 1e5f - 1.0f, 1e5f * 2e-7f);
}

TEST(Quadric, SmallSphereFarAwayAgreesWithALongDoubleReference) {
    // A sphere of radius 1e-3 seen from 1e5 away (1e8 radii): about the ray's origin,
    // b² − 4ac would cancel |o|² ≈ 1e10 against itself and lose the 1e-6 that decides hit or
    // miss even in double; about the box's middle nothing cancels. The reference solves the same
    // float ray and float coefficients in long double.
    Quadric q;
    q.coefficients = {1, 1, 1, 0, 0, 0, 0, 0, 0, -1e-6f};
    q.clip = {Vec3(-2e-3f), Vec3(2e-3f)};
    const long double r2 = -static_cast<long double>(q.coefficients[9]);
    const long double r = std::sqrt(r2);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int wrong = 0, hits = 0, counted = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 o = 1e5f * unit(Vec3(u(rng), u(rng), u(rng)));
        const Vec3 target = 1.25e-3f * Vec3(u(rng), u(rng), u(rng));
        const Vec3 d = unit(target - o);
        // Perpendicular distance of the float line from the centre: |o × d| / |d|.
        const long double ox = o.x, oy = o.y, oz = o.z, dx = d.x, dy = d.y, dz = d.z;
        const long double cx = oy * dz - oz * dy, cy = oz * dx - ox * dz, cz = ox * dy - oy * dx;
        const long double p =
            std::sqrt((cx * cx + cy * cy + cz * cz) / (dx * dx + dy * dy + dz * dz));
        if (std::fabs(p - r) <= 1e-6L * r) continue;  // the tangent band, as docs/stability.md
        ++counted;
        ShapeHit hit;
        const bool found = q.nearest(o, d, 0.0f, kInf, hit);
        hits += found;
        wrong += found != (p < r);
    }
    EXPECT_GT(hits, 200);
    EXPECT_EQ(wrong, 0) << "of " << counted;
}

TEST(Quadric, NearestIsTheFirstCrossingPastTnear) {
    // Over random lines through a hyperboloid of one sheet clipped off-centre: nearest() agrees
    // with the sorted crossings, which alternate entering and leaving.
    Quadric q;
    q.coefficients = {1, 0.5f, -1, 0.2f, 0, 0.1f, 0.3f, 0, 0, -1};
    q.clip = {Vec3(-2.0f, -1.5f, -1.0f), Vec3(2.5f, 2.0f, 1.5f)};
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 o = 4.0f * Vec3(u(rng), u(rng), u(rng));
        const Vec3 d = unit(Vec3(u(rng), u(rng), u(rng)) + Vec3(1e-3f));
        ShapeCrossing c[kMaxShapeCrossings];
        const int n = q.crossings(o, d, c);
        for (int k = 0; k < n; ++k) {
            EXPECT_EQ(c[k].entering, k % 2 == 0);
            if (k > 0) {
                EXPECT_LE(c[k - 1].t, c[k].t);
            }
        }
        ShapeHit hit;
        const bool found = q.nearest(o, d, 0.0f, kInf, hit);
        int first = 0;
        while (first < n && !(c[first].t > 0.0f)) ++first;
        ASSERT_EQ(found, first < n);
        if (found) {
            EXPECT_EQ(hit.t, c[first].t);
            ++checked;
        }
    }
    EXPECT_GT(checked, 200);
}

TEST(Quadric, ProblemsNameTheField) {
    EXPECT_FALSE(unit_sphere_quadric().problem());
    Quadric q = unit_sphere_quadric();
    q.coefficients = {0, 0, 0, 0, 0, 0, 0, 0, 0, -1};
    ASSERT_TRUE(q.problem());
    EXPECT_EQ(q.problem()->field, "coefficients");
    q = unit_sphere_quadric();
    q.coefficients[4] = std::numeric_limits<float>::infinity();
    ASSERT_TRUE(q.problem());
    EXPECT_EQ(q.problem()->field, "coefficients");
    q = unit_sphere_quadric(Vec3(0.0f), Vec3(1.0f, 1.0f, 0.0f));
    ASSERT_TRUE(q.problem());
    EXPECT_EQ(q.problem()->field, "bounds/max");
    q = unit_sphere_quadric(Vec3(1.0f), Vec3(0.0f));
    ASSERT_TRUE(q.problem());
}

TEST(Ellipsoid, HitsAlongEachAxisAndTheGradientNormal) {
    Ellipsoid e;
    e.center = Vec3(1.0f, 2.0f, 3.0f);
    e.radii = Vec3(2.0f, 1.0f, 0.5f);
    ShapeHit hit;
    ASSERT_TRUE(e.nearest(Vec3(-9.0f, 2.0f, 3.0f), Vec3(1, 0, 0), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 8.0f);
    expect_direction(hit.normal, Vec3(-1, 0, 0));
    ASSERT_TRUE(e.nearest(Vec3(1.0f, 2.0f, 13.0f), Vec3(0, 0, -1), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 9.5f);
    // Along y at x − 1 = 1: (y−2)² = 1 − 1/4, hit y = 2 − √0.75; ∇ ∝ ((x−1)/4, y − 2, 0).
    ASSERT_TRUE(e.nearest(Vec3(2.0f, -8.0f, 3.0f), Vec3(0, 1, 0), 0.0f, kInf, hit));
    const float y = -std::sqrt(0.75f);
    EXPECT_NEAR(hit.t, 10.0f + y, 1e-5f);
    expect_direction(hit.normal, Vec3(0.25f, y, 0.0f));
    e.radii.y = 0.0f;
    ASSERT_TRUE(e.problem());
    EXPECT_EQ(e.problem()->field, "radii");
}

TEST(Cylinder, SideAndCapsAtClosedFormDistances) {
    Cylinder c;
    c.base = Vec3(0.0f, 0.0f, 0.0f);
    c.top = Vec3(0.0f, 2.0f, 0.0f);
    c.radius = 1.0f;
    ShapeHit hit;
    ASSERT_TRUE(c.nearest(Vec3(-5.0f, 1.0f, 0.0f), Vec3(1, 0, 0), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 4.0f);
    expect_direction(hit.normal, Vec3(-1, 0, 0));
    // Up the axis: the bottom cap (a disc) at t = 5, the top cap at 7.
    ShapeCrossing x[kMaxShapeCrossings];
    ASSERT_EQ(c.crossings(Vec3(0.5f, -5.0f, 0.0f), Vec3(0, 1, 0), x), 2);
    EXPECT_FLOAT_EQ(x[0].t, 5.0f);
    EXPECT_FLOAT_EQ(x[1].t, 7.0f);
    ASSERT_TRUE(c.nearest(Vec3(0.5f, -5.0f, 0.0f), Vec3(0, 1, 0), 0.0f, kInf, hit));
    expect_direction(hit.normal, Vec3(0, -1, 0));
    // Just outside the radius the caps miss.
    EXPECT_EQ(c.crossings(Vec3(1.0005f, -5.0f, 0.0f), Vec3(0, 1, 0), x), 0);
    // Open: nothing along the axis; from inside the side at r.
    c.capped = false;
    EXPECT_EQ(c.crossings(Vec3(0.5f, -5.0f, 0.0f), Vec3(0, 1, 0), x), 0);
    ASSERT_TRUE(c.nearest(Vec3(0.5f, 1.0f, 0.0f), Vec3(1, 0, 0), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 0.5f);
    expect_direction(hit.normal, Vec3(1, 0, 0));
    c.top = c.base;
    ASSERT_TRUE(c.problem());
    EXPECT_EQ(c.problem()->field, "top");
}

TEST(Cylinder, TiltedAxis) {
    // Axis along (1, 1, 0)/√2 from the origin, length 4, radius 0.5: a ray along z through the
    // axis point (1, 1, 0) enters at z = −0.5 with normal −z.
    Cylinder c;
    c.top = Vec3(4.0f / std::sqrt(2.0f), 4.0f / std::sqrt(2.0f), 0.0f);
    c.radius = 0.5f;
    ShapeHit hit;
    ASSERT_TRUE(c.nearest(Vec3(1.0f, 1.0f, -5.0f), Vec3(0, 0, 1), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 4.5f, 1e-5f);
    expect_direction(hit.normal, Vec3(0, 0, -1));
    // Perpendicular to the axis in the xy plane through (1, 1, 0): crosses at ±0.5.
    const Vec3 across = unit(Vec3(1.0f, -1.0f, 0.0f));
    ASSERT_TRUE(c.nearest(Vec3(1.0f, 1.0f, 0.0f) - 3.0f * across, across, 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 2.5f, 1e-5f);
    expect_direction(hit.normal, -across);
    const Bounds3 b = c.bounds();
    EXPECT_LE(b.lower.x, -0.5f / std::sqrt(2.0f) + 1e-5f);
    EXPECT_GE(b.upper.y, 4.0f / std::sqrt(2.0f) + 0.5f / std::sqrt(2.0f) - 1e-5f);
}

TEST(Paraboloid, VertexRimAndTheLinearCaseAlongTheAxis) {
    Paraboloid p;  // y = x² + z² up to y = 1 (radius 1 at height 1)
    ShapeHit hit;
    // Along the axis a = 0: the single root is the vertex, t = 5, normal −y; leaves by the cap.
    ShapeCrossing x[kMaxShapeCrossings];
    ASSERT_EQ(p.crossings(Vec3(0.0f, -5.0f, 0.0f), Vec3(0, 1, 0), x), 2);
    EXPECT_FLOAT_EQ(x[0].t, 5.0f);
    EXPECT_FLOAT_EQ(x[1].t, 6.0f);
    ASSERT_TRUE(p.nearest(Vec3(0.0f, -5.0f, 0.0f), Vec3(0, 1, 0), 0.0f, kInf, hit));
    expect_direction(hit.normal, Vec3(0, -1, 0));
    // At x = 0.5: y = 0.25, ∇ ∝ (2x, −1, 0).
    ASSERT_TRUE(p.nearest(Vec3(0.5f, -5.0f, 0.0f), Vec3(0, 1, 0), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 5.25f);
    expect_direction(hit.normal, Vec3(1.0f, -1.0f, 0.0f));
    // Sideways at y = 0.64: x = ±0.8.
    ASSERT_TRUE(p.nearest(Vec3(-3.0f, 0.64f, 0.0f), Vec3(1, 0, 0), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 2.2f, 1e-5f);
    // From far along the axis the vertex keeps its relative accuracy.
    ASSERT_TRUE(p.nearest(Vec3(0.0f, -1e6f, 0.0f), Vec3(0, 1, 0), 0.0f, kInf, hit));
    EXPECT_EQ(hit.t, 1e6f);
}

TEST(Hyperboloid, OneSheetWaistAndTwoSheetVertices) {
    Hyperboloid h;
    h.radius = 1.0f;
    h.semi_axis = 2.0f;
    h.height = 4.0f;  // y in [−2, 2]; end radius √2
    ShapeHit hit;
    ASSERT_TRUE(h.nearest(Vec3(-5.0f, 0.0f, 0.0f), Vec3(1, 0, 0), 0.0f, kInf, hit));
    EXPECT_FLOAT_EQ(hit.t, 4.0f);
    expect_direction(hit.normal, Vec3(-1, 0, 0));
    // At y = 2: x² = 1 + 1 = 2; ∇ ∝ (2x, −2y/c² , 0) = (2√2, −1, 0).
    ASSERT_TRUE(h.nearest(Vec3(-5.0f, 2.0f - 1e-4f, 0.0f), Vec3(1, 0, 0), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 5.0f - std::sqrt(2.0f), 1e-3f);
    // Down the axis: the caps only.
    ShapeCrossing x[kMaxShapeCrossings];
    ASSERT_EQ(h.crossings(Vec3(0.0f, 5.0f, 0.0f), Vec3(0, -1, 0), x), 2);
    EXPECT_FLOAT_EQ(x[0].t, 3.0f);
    EXPECT_FLOAT_EQ(x[1].t, 7.0f);
    h.sheets = 2;
    h.height = 6.0f;  // vertices at y = ±2, ends at ±3
    ASSERT_EQ(h.crossings(Vec3(0.0f, 5.0f, 0.0f), Vec3(0, -1, 0), x), 4);
    const float expected[] = {2.0f, 3.0f, 7.0f, 8.0f};
    for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(x[i].t, expected[i]) << i;
    EXPECT_FALSE(h.problem());
    h.height = 4.0f;
    ASSERT_TRUE(h.problem());
    EXPECT_EQ(h.problem()->field, "height");
    h.sheets = 3;
    ASSERT_TRUE(h.problem());
    EXPECT_EQ(h.problem()->field, "sheets");
}

// Every end point of a shape's outline lies on its surface (|q| ~ 0), and there are some.
template <typename S>
void expect_outline_on_surface(const S& shape) {
    Outline outline(OutlineView{DVec3(0.0, 2.0, 20.0), 1e-3});
    shape.outline(outline);
    ASSERT_GT(outline.segments().size(), 16u) << S::kName;
    const ClippedQuadric q = shape.intersector();
    for (const OutlineSegment& s : outline.segments()) {
        EXPECT_NEAR(q.value(s.a), 0.0, 1e-9) << S::kName;
        EXPECT_NEAR(q.value(s.b), 0.0, 1e-9) << S::kName;
    }
}

TEST(QuadricForms, OutlinesLieOnTheSurface) {
    Ellipsoid e;
    e.radii = Vec3(2.0f, 1.0f, 0.5f);
    expect_outline_on_surface(e);
    Cylinder c;
    c.top = Vec3(1.0f, 2.0f, 0.5f);
    expect_outline_on_surface(c);
    Paraboloid p;
    p.axis = unit(Vec3(0.0f, 1.0f, 1.0f));
    expect_outline_on_surface(p);
    Hyperboloid h;
    expect_outline_on_surface(h);
    h.sheets = 2;
    h.semi_axis = 0.5f;
    expect_outline_on_surface(h);
}

TEST(Quadric, ThroughTheAccelAsUserGeometry) {
    Scene scene;
    scene.shapes.of<Quadric>().push_back(unit_sphere_quadric());
    Cylinder c;
    c.base = Vec3(0.0f, 0.0f, 5.0f);
    c.top = Vec3(0.0f, 0.0f, 6.0f);
    c.material = 1;
    scene.shapes.of<Cylinder>().push_back(c);
    AccelOptions options;
    const Accel accel(scene, options);
    Ray ray;
    ray.origin = Vec3(0.0f, 0.0f, 20.0f);
    ray.direction = Vec3(0, 0, -1);
    SurfaceHit hit;
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_EQ(hit.shape, Shapes::index_of<Cylinder>());
    EXPECT_FLOAT_EQ(hit.t, 14.0f);
    EXPECT_EQ(hit.geometric_normal, Vec3(0, 0, 1));
    ray.origin.z = 4.0f;
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_EQ(hit.shape, Shapes::index_of<Quadric>());
    EXPECT_FLOAT_EQ(hit.t, 3.0f);
    EXPECT_NEAR(hit.geometric_normal.z, 1.0f, 1e-6f);
}

}  // namespace
}  // namespace rayo
