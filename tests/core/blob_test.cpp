// Blobs (core/shapes/blob.h): a lone element is the sphere of radius R·√(1 − ∛(T/s)) (hits,
// normals, from inside, crossings); two elements bulge into a neck of closed-form radius; a sweep
// of grazing rays neither misses nor speckles against a brute-force reference; blobs in CSG.
#include "core/shapes/blob.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "core/accel.h"
#include "core/shapes/blob_mesh.h"
#include "core/shapes/csg.h"

namespace rayo {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

Blob one_element() {
    Blob b;
    b.elements = {{Vec3(1.0f, 2.0f, -3.0f), 2.0f, 1.5f}};
    b.threshold = 0.4f;
    return b;
}

TEST(Blob, LoneElementIsItsClosedFormSphere) {
    const Blob b = one_element();
    const double T = 0.4f, strength = 1.5f;  // as stored
    const double rho = 2.0 * std::sqrt(1.0 - std::cbrt(T / strength));
    EXPECT_NEAR(Blob::sphere_radius(b.elements[0], b.threshold), rho, 1e-12);
    EXPECT_NEAR(b.field(DVec3(1.0, 2.0 + rho, -3.0)), T, 1e-12);
    const Sphere sphere{Vec3(1.0f, 2.0f, -3.0f), static_cast<float>(rho), 0};
    // Rays from many directions at many offsets: the hit and the normal of the sphere.
    int hits = 0;
    for (int k = 0; k < 200; ++k) {
        const float a = 0.37f * k, c = std::cos(a), s = std::sin(a);
        const Vec3 d = glm::normalize(Vec3(c, 0.3f * s, s));
        const Vec3 side = glm::normalize(glm::cross(d, Vec3(0, 1, 0)));
        const Vec3 o = sphere.center - 10.0f * d + (0.01f * k - 1.0f) * side;
        ShapeHit expected, got;
        const bool sphere_hit = sphere.nearest(o, d, 0.0f, kInf, expected);
        ASSERT_EQ(b.nearest(o, d, 0.0f, kInf, got), sphere_hit) << k;
        if (!sphere_hit) continue;
        ++hits;
        EXPECT_NEAR(got.t, expected.t, 2e-5f) << k;
        EXPECT_GT(glm::dot(glm::normalize(got.normal), glm::normalize(expected.normal)), 0.99999f)
            << k;
    }
    EXPECT_GT(hits, 100);
}

TEST(Blob, FromInsideAndAsCrossings) {
    const Blob b = one_element();
    const double rho = Blob::sphere_radius(b.elements[0], b.threshold);
    ShapeHit hit;
    ASSERT_TRUE(b.nearest(Vec3(1.0f, 2.0f, -3.0f), Vec3(0, 1, 0), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, rho, 1e-6);
    EXPECT_GT(glm::normalize(hit.normal).y, 0.99999f);  // outward
    ShapeCrossing c[kMaxShapeCrossings];
    ASSERT_EQ(b.crossings(Vec3(1.0f, -8.0f, -3.0f), Vec3(0, 1, 0), c), 2);
    EXPECT_NEAR(c[0].t, 10.0 - rho, 1e-5);
    EXPECT_TRUE(c[0].entering);
    EXPECT_LT(glm::normalize(c[0].normal).y, -0.99999f);
    EXPECT_NEAR(c[1].t, 10.0 + rho, 1e-5);
    EXPECT_FALSE(c[1].entering);
    // Outside the window, or past the support: nothing.
    EXPECT_FALSE(b.nearest(Vec3(1.0f, -8.0f, -3.0f), Vec3(0, 1, 0), 0.0f, 8.5f, hit));
    EXPECT_FALSE(b.nearest(Vec3(1.0f, -8.0f, -0.5f), Vec3(0, 1, 0), 0.0f, kInf, hit));
}

TEST(Blob, TwoElementsBulgeIntoANeckOfClosedFormRadius) {
    // Unit elements (R = 1, s = 1) at x = ±D/2: in the midplane x = 0 both terms are equal, so
    // the surface there is 2·(1 − (D²/4 + y²))³ = T, a circle of radius
    // y = √(1 − ∛(T/2) − D²/4) — wider than nothing, where a lone element's sphere (radius
    // √(1 − ∛T) = 0.54 for T = 0.5) would not reach x = 0 at all for D/2 = 0.6.
    const double D = 1.2, T = 0.5;
    Blob b;
    b.elements = {{Vec3(float(-D / 2), 0, 0), 1.0f, 1.0f}, {Vec3(float(D / 2), 0, 0), 1.0f, 1.0f}};
    b.threshold = float(T);
    const double neck = std::sqrt(1.0 - std::cbrt(T / 2.0) - D * D / 4.0);
    ASSERT_GT(neck, 0.1);
    ASSERT_LT(Blob::sphere_radius(b.elements[0], T), D / 2);
    ShapeHit hit;
    ASSERT_TRUE(b.nearest(Vec3(0, 5, 0), Vec3(0, -1, 0), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 5.0 - neck, 1e-5);
    EXPECT_GT(glm::normalize(hit.normal).y, 0.99999f);  // symmetric: straight up
    // Along the axis, beyond the other element's support, the outer cap is a lone sphere's.
    const double rho = Blob::sphere_radius(b.elements[0], T);
    ASSERT_GT(D / 2 + rho - (-D / 2), 1.0);  // the cap lies outside the far element's support
    ASSERT_TRUE(b.nearest(Vec3(5, 0, 0), Vec3(-1, 0, 0), 0.0f, kInf, hit));
    EXPECT_NEAR(hit.t, 5.0 - (D / 2 + rho), 1e-5);
}

// max over t of g(t) = F(o + t·d) − T by brute force: fine samples, then golden-section
// refinement around the best.
double max_along(const Blob& b, const DVec3& o, const DVec3& d, double t0, double t1) {
    const int n = 4000;
    double best_t = t0, best = -1e300;
    for (int i = 0; i <= n; ++i) {
        const double t = t0 + (t1 - t0) * i / n;
        const double v = b.field(o + t * d);
        if (v > best) best = v, best_t = t;
    }
    double a = best_t - (t1 - t0) / n, c = best_t + (t1 - t0) / n;
    for (int i = 0; i < 100; ++i) {
        const double m1 = a + (c - a) * 0.382, m2 = a + (c - a) * 0.618;
        if (b.field(o + m1 * d) > b.field(o + m2 * d)) {
            c = m2;
        } else {
            a = m1;
        }
    }
    return std::max(best, b.field(o + 0.5 * (a + c) * d)) - b.threshold;
}

TEST(Blob, GrazingRaysNeitherMissNorSpeckle) {
    // Three elements, one negative; rays parallel to z swept finely across the silhouette and
    // across the saddle between the elements. A ray must hit exactly when the field along it
    // rises above the threshold (by a margin that float origins can resolve).
    Blob b;
    b.elements = {{Vec3(-0.6f, 0, 0), 1.0f, 1.0f},
                  {Vec3(0.6f, 0.1f, 0.2f), 0.9f, 1.2f},
                  {Vec3(0.0f, 0.5f, 0.0f), 0.5f, -0.4f}};
    b.threshold = 0.5f;
    int hits = 0, misses = 0, checked = 0;
    for (int j = 0; j < 120; ++j) {
        for (int i = 0; i < 120; ++i) {
            const Vec3 o(-1.8f + 3.6f * i / 119.0f, -1.2f + 2.4f * j / 119.0f, 5.0f);
            const Vec3 d(0, 0, -1);
            const double peak = max_along(b, DVec3(o), DVec3(d), 3.0, 7.0);
            if (std::abs(peak) < 1e-6) continue;  // tangent within float resolution: either
            ++checked;
            ShapeHit hit;
            const bool got = b.nearest(o, d, 0.0f, kInf, hit);
            ASSERT_EQ(got, peak > 0.0) << "ray at " << o.x << ", " << o.y << " peak " << peak;
            if (got) {
                ++hits;
                EXPECT_NEAR(b.field(DVec3(o) + double(hit.t) * DVec3(d)), b.threshold, 1e-5);
            } else {
                ++misses;
            }
        }
    }
    EXPECT_GT(hits, 1000);
    EXPECT_GT(misses, 1000);
    // And right at a lone element's silhouette: ρ(1 ∓ 1e−5) hit and miss.
    const Blob lone = one_element();
    const double rho = Blob::sphere_radius(lone.elements[0], lone.threshold);
    for (int k = 0; k < 100; ++k) {
        const double angle = 0.0628 * k;
        const DVec3 offset(std::cos(angle), std::sin(angle), 0.0);
        ShapeHit hit;
        const DVec3 c(lone.elements[0].center);
        EXPECT_TRUE(lone.nearest(Vec3(c + rho * (1 - 1e-5) * offset + DVec3(0, 0, 9)),
                                 Vec3(0, 0, -1), 0.0f, kInf, hit))
            << k;
        EXPECT_FALSE(lone.nearest(Vec3(c + rho * (1 + 1e-5) * offset + DVec3(0, 0, 9)),
                                  Vec3(0, 0, -1), 0.0f, kInf, hit))
            << k;
    }
}

TEST(Blob, BoundsAndProblems) {
    Blob b = one_element();
    EXPECT_FALSE(b.problem());
    EXPECT_EQ(b.bounds().lower, Vec3(-1.0f, 0.0f, -5.0f));
    EXPECT_EQ(b.bounds().upper, Vec3(3.0f, 4.0f, -1.0f));
    b.threshold = 1.5f;
    ASSERT_TRUE(b.problem());
    EXPECT_EQ(b.problem()->field, "threshold");
    b.elements.clear();
    ASSERT_TRUE(b.problem());
    EXPECT_EQ(b.problem()->field, "elements");
}

TEST(Blob, InCsgAndThroughTheAccel) {
    // A blob minus a box that cuts off its top half: down the axis, the cut face at y = 2.
    Csg csg;
    const int blob = csg.add_leaf(one_element());
    Box box;
    box.min = Vec3(-5.0f, 2.0f, -8.0f);
    box.max = Vec3(5.0f, 9.0f, 2.0f);
    const int cut = csg.add_leaf(box);
    csg.add_operation(CsgOp::Difference, blob, cut);
    EXPECT_EQ(csg.leaf_budget(), 2 + kMaxShapeCrossings);
    Scene scene;
    scene.shapes.of<Csg>().push_back(csg);
    scene.shapes.of<Blob>().push_back(one_element());
    scene.shapes.of<Blob>().back().elements[0].center.x += 10.0f;
    const Accel accel(scene, AccelOptions{});
    Ray ray;
    ray.origin = Vec3(1.0f, 20.0f, -3.0f);
    ray.direction = Vec3(0, -1, 0);
    SurfaceHit hit;
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_EQ(hit.shape, Shapes::index_of<Csg>());
    EXPECT_NEAR(hit.t, 18.0f, 1e-5f);
    EXPECT_GT(hit.geometric_normal.y, 0.99999f);
    ray.origin.x = 11.0f;
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_EQ(hit.shape, Shapes::index_of<Blob>());
    EXPECT_NEAR(hit.t, 18.0 - Blob::sphere_radius(one_element().elements[0], 0.4), 1e-5);
}

TEST(Blob, MarchingTetrahedraMeshIsClosedAndOnTheSurface) {
    // A lone element's mesh: every vertex within a small fraction of a cell of the sphere (the
    // edge interpolation's error), normals radial, every edge shared by exactly two triangles.
    const Blob b = one_element();
    const double rho = Blob::sphere_radius(b.elements[0], b.threshold), cell = 0.1;
    const TriangleMesh mesh = tessellate_blob(b, cell);
    ASSERT_GT(mesh.triangle_count(), 500u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    const Vec3 c = b.elements[0].center;
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3 offset = mesh.positions[i] - c;
        EXPECT_NEAR(glm::length(offset), rho, 0.05 * cell) << i;
        EXPECT_GT(glm::dot(glm::normalize(offset), mesh.normals[i]), 0.9999f) << i;
    }
    std::map<std::pair<uint32_t, uint32_t>, int> edges;
    for (const auto& t : mesh.triangles) {
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = t[e], z = t[(e + 1) % 3];
            ++edges[{std::min(a, z), std::max(a, z)}];
        }
        // Wound outward: the face normal points away from the centre.
        const Vec3 &p0 = mesh.positions[t[0]], &p1 = mesh.positions[t[1]],
                   &p2 = mesh.positions[t[2]];
        EXPECT_GT(glm::dot(glm::cross(p1 - p0, p2 - p0), p0 + p1 + p2 - 3.0f * c), 0.0f);
    }
    for (const auto& edge : edges) ASSERT_EQ(edge.second, 2);
}

}  // namespace
}  // namespace rayo
