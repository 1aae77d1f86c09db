// Voxel grids (core/shapes/voxel_grid.h): a sphere voxelized here is hit at its radius within a
// voxel with normals near the sphere's; composite of a constant-density slab equals the closed
// form; the transfer ramp; several volumes in the order of entry; raw decoding of the three
// formats.
#include "core/shapes/voxel_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/test_helpers.h"

namespace rayo {
namespace {

// A sphere of radius r about the origin in [−1, 1]³: value 0.5 + (r − |p|)/(2·voxel), clamped
// to [0, 1], so the 0.5 iso-surface is the sphere.
VoxelGrid voxel_sphere(int n, float r) {
    VoxelGrid g;
    g.dims[0] = g.dims[1] = g.dims[2] = n;
    g.lower = Vec3(-1.0f);
    g.size = Vec3(2.0f);
    const float voxel = 2.0f / float(n);
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                const Vec3 p = g.lower + voxel * Vec3(i + 0.5f, j + 0.5f, k + 0.5f);
                const float v = 0.5f + (r - glm::length(p)) / (2.0f * voxel);
                g.values.push_back(std::clamp(v, 0.0f, 1.0f));
            }
        }
    }
    return g;
}

TEST(VoxelGrid, VoxelizedSphereHitAtItsRadiusWithItsNormal) {
    const int n = 40;
    const float r = 0.7f, voxel = 2.0f / n;
    const VoxelGrid g = voxel_sphere(n, r);
    int hits = 0;
    for (int a = 0; a < 24; ++a) {
        for (int b = 0; b < 12; ++b) {
            // Rays from a shell of radius 3 toward points near the centre.
            const float theta = 0.13f + 2.9f * float(b) / 11.0f, phi = 0.261f * float(a);
            const Vec3 origin = 3.0f * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                            std::sin(theta) * std::sin(phi));
            const Vec3 target(0.3f * std::sin(1.7f * a), 0.25f * std::cos(2.3f * b), 0.1f);
            const Vec3 d = glm::normalize(target - origin);
            // The exact sphere's hit, from the quadratic.
            const float bq = glm::dot(origin, d), cq = glm::dot(origin, origin) - r * r;
            const float disc = bq * bq - cq;
            ShapeHit hit;
            const bool found = g.nearest(origin, d, 0.0f, 100.0f, hit);
            if (disc < voxel * voxel) continue;  // grazing: within a voxel of the silhouette
            ASSERT_TRUE(found) << a << " " << b;
            const float t_exact = -bq - std::sqrt(disc);
            EXPECT_NEAR(hit.t, t_exact, voxel) << a << " " << b;
            const Vec3 p = origin + hit.t * d;
            EXPECT_NEAR(glm::length(p), r, 0.25f * voxel);
            const float cosine = glm::dot(glm::normalize(hit.normal), glm::normalize(p));
            EXPECT_GT(cosine, std::cos(3.0f * kPi / 180.0f)) << a << " " << b;  // within 3°
            ++hits;
        }
    }
    EXPECT_GT(hits, 200);
    // Rays that miss the sphere miss the grid's surface; tfar bounds the hit.
    ShapeHit hit;
    EXPECT_FALSE(g.nearest(Vec3(0.9f, -3.0f, 0.9f), Vec3(0, 1, 0), 0.0f, 100.0f, hit));
    EXPECT_FALSE(g.nearest(Vec3(0.0f, -3.0f, 0.0f), Vec3(0, 1, 0), 0.0f, 2.0f, hit));
    // From inside, the first crossing is the way out, normal still outward.
    ASSERT_TRUE(g.nearest(Vec3(0.0f), Vec3(1, 0, 0), 0.0f, 100.0f, hit));
    EXPECT_NEAR(hit.t, r, 0.25f * voxel);
    EXPECT_GT(hit.normal.x, 0.0f);
}

TEST(VoxelGrid, CompositeOfAConstantSlabIsTheClosedForm) {
    VoxelGrid g;
    g.dims[0] = 5;
    g.dims[1] = 7;
    g.dims[2] = 3;
    g.values.assign(5 * 7 * 3, 0.6f);
    g.lower = Vec3(0.0f, 0.0f, 0.0f);
    g.size = Vec3(2.0f, 3.0f, 1.5f);
    const Vec3 c(0.9f, 0.5f, 0.2f);
    const float sigma_per_value = 1.3f;
    const auto transfer = [&](float v, Vec3& colour, float& sigma) {
        colour = c;
        sigma = sigma_per_value * v;
    };
    for (const Vec3& d : {Vec3(0, 0, 1), glm::normalize(Vec3(0.3f, 0.2f, 1.0f)),
                          glm::normalize(Vec3(1.0f, 1.0f, 0.4f))}) {
        const Vec3 origin = Vec3(0.7f, 1.1f, 0.0f) - 5.0f * d;
        float t_enter, t_exit;
        Vec3 n0, n1;
        ASSERT_TRUE((Box{g.lower, g.lower + g.size}.slabs(origin, d, t_enter, n0, t_exit, n1)));
        const float length = t_exit - t_enter;
        float transmittance;
        const Vec3 colour = g.composite(origin, d, 0.0f, 100.0f, transfer, transmittance);
        const float expected_t = std::exp(-sigma_per_value * 0.6f * length);
        EXPECT_NEAR(transmittance, expected_t, 1e-5f);
        rayo_test::expect_vec_near(colour, c * (1.0f - expected_t), 1e-5);
        // A part of the segment: the closed form of its length.
        g.composite(origin, d, t_enter + 0.25f * length, t_enter + 0.5f * length, transfer,
                    transmittance);
        EXPECT_NEAR(transmittance, std::exp(-sigma_per_value * 0.6f * 0.25f * length), 1e-5f);
    }
}

TEST(VoxelGrid, TransferRampInterpolatesLinearlyAndHoldsItsEnds) {
    VoxelTransfer transfer;
    transfer.stops = {{0.2f, Vec3(1.0f, 0.0f, 0.0f), 0.0f},
                      {0.6f, Vec3(0.0f, 1.0f, 0.0f), 4.0f},
                      {0.6f, Vec3(0.0f, 0.0f, 1.0f), 8.0f},  // a step at 0.6
                      {1.0f, Vec3(0.0f, 0.0f, 0.0f), 6.0f}};
    Vec3 c;
    float sigma;
    transfer(-3.0f, c, sigma);  // below the first stop: the first
    rayo_test::expect_vec_near(c, Vec3(1, 0, 0), 0.0);
    EXPECT_EQ(sigma, 0.0f);
    transfer(0.3f, c, sigma);  // a quarter of the way from 0.2 to 0.6
    rayo_test::expect_vec_near(c, Vec3(0.75f, 0.25f, 0.0f), 1e-6);
    EXPECT_NEAR(sigma, 1.0f, 1e-6f);
    transfer(0.6f, c, sigma);  // at the step: the later stop
    rayo_test::expect_vec_near(c, Vec3(0, 0, 1), 0.0);
    EXPECT_EQ(sigma, 8.0f);
    transfer(0.9f, c, sigma);
    rayo_test::expect_vec_near(c, Vec3(0.0f, 0.0f, 0.25f), 1e-6);
    EXPECT_NEAR(sigma, 6.5f, 1e-5f);
    transfer(7.0f, c, sigma);  // above the last: the last
    EXPECT_EQ(sigma, 6.0f);
    // The default: white, density 0 at 0 to 1 at 1.
    VoxelTransfer{}(0.25f, c, sigma);
    rayo_test::expect_vec_near(c, Vec3(1.0f), 0.0);
    EXPECT_NEAR(sigma, 0.25f, 1e-7f);
}

// Two constant slabs one behind the other along z, listed back first: composite_volumes takes
// them in the order the ray enters them, C1 + T1·C2, and skips a grid the segment misses.
TEST(VoxelGrid, VolumesCompositeInTheOrderTheRayEntersThem) {
    const auto slab = [](float z0, const Vec3& colour, float density) {
        VoxelGrid g;
        g.dims[0] = g.dims[1] = g.dims[2] = 2;
        g.values.assign(8, 1.0f);
        g.lower = Vec3(-1.0f, -1.0f, z0);
        g.size = Vec3(2.0f, 2.0f, 1.0f);
        g.mode = VoxelMode::Composite;
        g.transfer.stops = {{0.0f, colour, density}};
        return g;
    };
    const VoxelGrid back = slab(-3.0f, Vec3(0.0f, 0.0f, 1.0f), 2.0f);
    const VoxelGrid front = slab(0.0f, Vec3(1.0f, 0.0f, 0.0f), 0.5f);
    VoxelGrid moved = slab(0.0f, Vec3(0.0f, 1.0f, 0.0f), 50.0f);
    moved.lower.x = 5.0f;  // beside the ray
    const VoxelGrid* volumes[3] = {&back, &moved, &front};
    const Vec3 origin(0.0f, 0.0f, 5.0f), d(0.0f, 0.0f, -1.0f);
    float t;
    const Vec3 colour = composite_volumes(volumes, 3, origin, d, 0.0f, 100.0f, t);
    const float t1 = std::exp(-0.5f), t2 = std::exp(-2.0f);
    rayo_test::expect_vec_near(colour, Vec3(1.0f - t1, 0.0f, t1 * (1.0f - t2)), 1e-5);
    EXPECT_NEAR(t, t1 * t2, 1e-6f);
    // A segment that ends before the back slab sees the front one alone.
    composite_volumes(volumes, 3, origin, d, 0.0f, 7.0f, t);
    EXPECT_NEAR(t, t1, 1e-6f);
    // None: all light through.
    EXPECT_EQ(composite_volumes(volumes, 0, origin, d, 0.0f, 100.0f, t), Vec3(0.0f));
    EXPECT_EQ(t, 1.0f);
}

TEST(VoxelGrid, RawFormatsDecode) {
    EXPECT_EQ(decode_voxels(std::string("\x00\xff\x33", 3), VoxelFormat::U8),
              (std::vector<float>{0.0f, 1.0f, 0.2f}));
    EXPECT_EQ(decode_voxels(std::string("\xff\xff\x01\x00", 4), VoxelFormat::U16),
              (std::vector<float>{1.0f, 1.0f / 65535.0f}));
    EXPECT_EQ(decode_voxels(std::string("\x00\x00\xc0\x3f", 4), VoxelFormat::F32),
              (std::vector<float>{1.5f}));
}

}  // namespace
}  // namespace rayo
