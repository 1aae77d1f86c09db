// Height fields (core/shapes/height_field.h): the traversal against closed forms (a planar
// ramp), against a brute-force test of every triangle for rays along grid lines, diagonals and
// through cell corners (no leaks between cells), the tessellation's triangles and normals, and
// the field through the accel.
#include "core/shapes/height_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/accel.h"
#include "core/scene.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

// A ramp rising along x: height(x) = slope·(x − lower.x), size.y = 1 (samples in world units).
HeightField ramp(int columns, int rows, float rise) {
    HeightField f;
    f.columns = columns;
    f.rows = rows;
    f.lower = Vec3(-2.0f, 0.5f, -3.0f);
    f.size = Vec3(4.0f, 1.0f, 6.0f);
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) f.heights.push_back(rise * float(i) / float(columns - 1));
    }
    f.finish();
    return f;
}

// A bumpy field with pseudo-random heights in [0, 1].
HeightField bumpy(int columns, int rows) {
    HeightField f;
    f.columns = columns;
    f.rows = rows;
    f.lower = Vec3(0.0f);
    f.size = Vec3(float(columns - 1), 1.0f, float(rows - 1));  // unit cells
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
            uint32_t h = uint32_t(i) * 73856093u ^ uint32_t(j) * 19349663u;
            h = (h ^ (h >> 13)) * 0x5bd1e995u;
            f.heights.push_back(float(h >> 8) / float(1u << 24));
        }
    }
    f.finish();
    return f;
}

// The nearest hit over every triangle of the tessellation, in double, with no tolerance.
double brute_force_t(const HeightField& f, const Vec3& o, const Vec3& d) {
    const TriangleMesh mesh = f.tessellate();
    double best = std::numeric_limits<double>::infinity();
    const DVec3 origin(o), direction(d);
    for (const auto& tri : mesh.triangles) {
        const DVec3 p0(mesh.positions[tri[0]]), p1(mesh.positions[tri[1]]),
            p2(mesh.positions[tri[2]]);
        const DVec3 e1 = p1 - p0, e2 = p2 - p0, p = glm::cross(direction, e2);
        const double det = glm::dot(e1, p);
        if (det == 0.0) continue;
        const DVec3 s = origin - p0, q = glm::cross(s, e1);
        const double u = glm::dot(s, p) / det, v = glm::dot(direction, q) / det;
        const double t = glm::dot(e2, q) / det;
        if (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0 && t < best) best = t;
    }
    return best;
}

TEST(HeightField, RampHitAtTheClosedFormPoint) {
    const float rise = 2.0f;
    const HeightField f = ramp(17, 9, rise);
    // The plane y = 0.5 + rise·(x + 2)/4 (the ramp's surface), normal ∝ (−rise/4, 1, 0).
    const Vec3 normal = glm::normalize(Vec3(-rise / 4.0f, 1.0f, 0.0f));
    const Vec3 on_plane(-2.0f, 0.5f, 0.0f);
    const Vec3 origins[] = {Vec3(0.3f, 5.0f, 1.1f), Vec3(-1.7f, 4.0f, -2.9f),
                            Vec3(5.0f, 6.0f, 0.2f), Vec3(-6.0f, 6.0f, 2.0f)};
    const Vec3 targets[] = {Vec3(0.3f, 0.0f, 1.1f), Vec3(1.0f, 0.0f, 2.0f),
                            Vec3(-1.0f, 0.0f, -1.0f), Vec3(1.9f, 0.0f, -2.5f)};
    for (int k = 0; k < 4; ++k) {
        const Vec3 d = glm::normalize(targets[k] - origins[k]);
        const double t_plane =
            glm::dot(on_plane - origins[k], normal) / double(glm::dot(d, normal));
        ShapeHit hit;
        ASSERT_TRUE(f.nearest(origins[k], d, 0.0f, 1e30f, hit)) << "ray " << k;
        EXPECT_NEAR(hit.t, t_plane, 1e-4 * t_plane) << "ray " << k;
        rayo_test::expect_vec_near(glm::normalize(hit.normal), normal, 1e-5);
    }
    // Outside the footprint nothing is hit, and tfar bounds the hit.
    ShapeHit hit;
    EXPECT_FALSE(f.nearest(Vec3(2.5f, 5.0f, 0.0f), Vec3(0, -1, 0), 0.0f, 1e30f, hit));
    EXPECT_FALSE(f.nearest(Vec3(0.0f, 5.0f, 0.0f), Vec3(0, -1, 0), 0.0f, 2.0f, hit));
}

TEST(HeightField, GridLinesDiagonalsAndCornersDoNotLeak) {
    // 40 × 37 cells: more than two blocks each way, so block borders are crossed too.
    const HeightField f = bumpy(41, 38);
    int rays = 0;
    for (int i = 0; i <= 40; i += 3) {
        for (int j = 0; j <= 37; j += 4) {
            // Straight down through a sample (a cell corner), and slanting along the grid line
            // x = i, the line z = j and the diagonal through the corner.
            const Vec3 corner(float(i), 3.0f, float(j));
            const Vec3 directions[] = {
                Vec3(0, -1, 0),        Vec3(0, -1, 0.5f),       Vec3(0, -1, -0.5f),
                Vec3(0.5f, -1, 0),     Vec3(-0.5f, -1, 0),      Vec3(0.5f, -1, 0.5f),
                Vec3(-0.5f, -1, 0.5f), Vec3(0.3f, -0.1f, 0.3f), Vec3(1.0f, -0.05f, 0.0f)};
            for (Vec3 d : directions) {
                d = glm::normalize(d);
                const double expected = brute_force_t(f, corner, d);
                ShapeHit hit;
                const bool found = f.nearest(corner, d, 0.0f, 1e30f, hit);
                ASSERT_EQ(found, std::isfinite(expected))
                    << "from (" << i << ", " << j << ") along " << d.x << " " << d.y << " " << d.z;
                if (found) {
                    EXPECT_NEAR(hit.t, expected, 1e-4 * (1.0 + expected));
                }
                ++rays;
            }
        }
    }
    EXPECT_GT(rays, 1000);
}

TEST(HeightField, FarRaysThroughCornersOfALargeFieldDoNotLeak) {
    // 1024² cells of 0.1, seen from about 1.5 field widths away (as the bench's camera): float
    // error in the edge tests grows with the distance in cells.
    HeightField f;
    f.columns = f.rows = 1025;
    f.lower = Vec3(-51.2f, 0.0f, -51.2f);
    f.size = Vec3(102.4f, 1.0f, 102.4f);
    f.heights.assign(size_t(1025) * 1025, 0.25f);
    f.finish();
    const Vec3 eye(-70.0f, 45.0f, -70.0f);
    int leaks = 0, rays = 0;
    for (int j = 1; j < 1024; j += 7) {
        for (int i = 1; i < 1024; i += 7) {
            const Vec3 corner = f.vertex(i, j);
            const Vec3 d = glm::normalize(corner - eye);
            ShapeHit hit;
            ++rays;
            if (!f.nearest(eye, d, 0.0f, 1e30f, hit)) {
                ++leaks;
                continue;
            }
            EXPECT_NEAR(hit.t, glm::length(corner - eye), 1e-3f);
        }
    }
    EXPECT_EQ(leaks, 0) << "of " << rays << " rays through sample points";
}

TEST(HeightField, TessellationMatchesTheTraversalsTriangles) {
    HeightField f = bumpy(5, 4);
    f.smooth = true;
    f.material = 7;
    const TriangleMesh mesh = f.tessellate();
    ASSERT_EQ(mesh.triangles.size(), 2 * 4 * 3u);
    ASSERT_EQ(mesh.normals.size(), 20u);
    EXPECT_EQ(mesh.materials, std::vector<uint32_t>(24, 7u));
    for (size_t part = 0; part < mesh.triangles.size(); ++part) {
        uint32_t c[3];
        f.triangle(uint32_t(part), c);
        const Vec3 p0 = mesh.positions[c[0]], p1 = mesh.positions[c[1]], p2 = mesh.positions[c[2]];
        EXPECT_GT(glm::cross(p1 - p0, p2 - p0).y, 0.0f) << "winding faces up, part " << part;
    }
    // A flat field's vertex normals point straight up; a ramp's are the plane's.
    const HeightField r = ramp(4, 4, 4.0f);
    rayo_test::expect_vec_near(r.vertex_normal(0, 0), glm::normalize(Vec3(-1, 1, 0)), 1e-6);
    rayo_test::expect_vec_near(r.vertex_normal(2, 3), glm::normalize(Vec3(-1, 1, 0)), 1e-6);
}

TEST(HeightField, ThroughTheAccelTheTraversalAndTheMeshAgree) {
    HeightField f = bumpy(33, 29);
    f.smooth = true;
    Scene traversal, mesh;
    traversal.heightfields.push_back(f);
    mesh.meshes.push_back(f.tessellate());
    const Accel a(traversal), b(mesh);
    int hits = 0;
    for (int k = 0; k < 400; ++k) {
        Ray ray;
        ray.origin = Vec3(-5.0f, 4.0f, -3.0f);
        const Vec3 target(0.5f + float(k % 20) * 1.6f, 0.0f, 0.3f + float(k / 20) * 1.4f);
        ray.direction = glm::normalize(target - ray.origin);
        SurfaceHit ha, hb;
        const bool fa = a.intersect(ray, ha), fb = b.intersect(ray, hb);
        ASSERT_EQ(fa, fb) << "ray " << k;
        if (!fa) continue;
        ++hits;
        EXPECT_EQ(ha.shape, kHeightFieldShape);
        EXPECT_NEAR(ha.t, hb.t, 1e-4f * hb.t) << "ray " << k;
        // On the diagonal between a cell's two triangles either may report the hit.
        EXPECT_EQ(ha.primitive >> 1, hb.primitive >> 1) << "ray " << k;
        if (ha.primitive != hb.primitive) continue;
        rayo_test::expect_vec_near(ha.geometric_normal, hb.geometric_normal, 1e-5);
        rayo_test::expect_vec_near(ha.shading_normal, hb.shading_normal, 1e-3);
        EXPECT_EQ(a.occluded(ray), true);
    }
    EXPECT_GT(hits, 300);
}

}  // namespace
}  // namespace rayo
