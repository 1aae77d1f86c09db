// Worley cellular noise (seed 003 "Mapa celular"): F1 ≤ F2 ≤ F3, the neighbour search against brute
// force (the printed code visited cell + i·j·n instead of the 3×3 block), the metrics, continuity
// across negative coordinates, golden values and seeding.
#include "shading/cellular.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shading/noise.h"

namespace rayo {
namespace {

float metric_distance(DistanceMetric m, float dx, float dy, float dz) {
    dx = std::fabs(dx), dy = std::fabs(dy), dz = std::fabs(dz);
    switch (m) {
        case DistanceMetric::Manhattan:
            return dx + dy + dz;
        case DistanceMetric::Chebyshev:
            return std::max(dx, std::max(dy, dz));
        case DistanceMetric::Euclidean:
            break;
    }
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// The three smallest distances to the feature points of the (2r+1)² block around p's cell.
std::vector<float> brute_force_2d(float x, float y, uint32_t seed, DistanceMetric m, int r) {
    const int cx = static_cast<int>(std::floor(x)), cy = static_cast<int>(std::floor(y));
    std::vector<float> d;
    for (int j = -r; j <= r; ++j) {
        for (int i = -r; i <= r; ++i) {
            float fx, fy;
            cellular_feature_2d(cx + i, cy + j, seed, fx, fy);
            d.push_back(metric_distance(m, fx - x, fy - y, 0.0f));
        }
    }
    std::partial_sort(d.begin(), d.begin() + 3, d.end());
    d.resize(3);
    return d;
}

std::vector<float> brute_force_3d(const Vec3& p, uint32_t seed, DistanceMetric m, int r) {
    const int cx = static_cast<int>(std::floor(p.x)), cy = static_cast<int>(std::floor(p.y)),
              cz = static_cast<int>(std::floor(p.z));
    std::vector<float> d;
    for (int k = -r; k <= r; ++k) {
        for (int j = -r; j <= r; ++j) {
            for (int i = -r; i <= r; ++i) {
                const Vec3 f = cellular_feature_3d(cx + i, cy + j, cz + k, seed);
                d.push_back(metric_distance(m, f.x - p.x, f.y - p.y, f.z - p.z));
            }
        }
    }
    std::partial_sort(d.begin(), d.begin() + 3, d.end());
    d.resize(3);
    return d;
}

Vec3 point(int i, float extent) {
    const uint32_t h = hash_u32(static_cast<uint32_t>(i) * 7919u + 1u);
    return Vec3((unit_float(h) - 0.5f) * 2 * extent,
                (unit_float(hash_u32(h + 1)) - 0.5f) * 2 * extent,
                (unit_float(hash_u32(h + 2)) - 0.5f) * 2 * extent);
}

const DistanceMetric kMetrics[] = {DistanceMetric::Euclidean, DistanceMetric::Manhattan,
                                   DistanceMetric::Chebyshev};

// The fixed neighbour search finds the true nearest three, checked against brute force over a
// 5×5 block and a 7×7 block (2-D) and a 5×5×5 block (3-D). A search of the 3×3 block alone differs
// from brute force at some points (counted), so the comparison can tell the two apart.
TEST(Cellular, NeighbourSearchMatchesBruteForce) {
    for (DistanceMetric m : kMetrics) {
        int three_by_three_wrong = 0;
        for (int i = 0; i < 20000; ++i) {
            const Vec3 p = point(i, 200.0f);
            const CellularDistances d = cellular_2d(p.x, p.y, 21, m);
            const std::vector<float> b5 = brute_force_2d(p.x, p.y, 21, m, 2);
            const std::vector<float> b7 = brute_force_2d(p.x, p.y, 21, m, 3);
            ASSERT_FLOAT_EQ(d.f1, b5[0]) << "point " << i;
            ASSERT_FLOAT_EQ(d.f2, b5[1]) << "point " << i;
            ASSERT_FLOAT_EQ(d.f3, b5[2]) << "point " << i;
            ASSERT_FLOAT_EQ(d.f3, b7[2]) << "point " << i;
            const std::vector<float> b3 = brute_force_2d(p.x, p.y, 21, m, 1);
            three_by_three_wrong += b3 != b5;
        }
        EXPECT_GT(three_by_three_wrong, 0);
        for (int i = 0; i < 3000; ++i) {
            const Vec3 p = point(i, 200.0f);
            const CellularDistances d = cellular_3d(p, 22, m);
            const std::vector<float> b = brute_force_3d(p, 22, m, 2);
            ASSERT_FLOAT_EQ(d.f1, b[0]) << "point " << i;
            ASSERT_FLOAT_EQ(d.f2, b[1]) << "point " << i;
            ASSERT_FLOAT_EQ(d.f3, b[2]) << "point " << i;
        }
    }
}

TEST(Cellular, DistancesAreOrderedAndCombinationInUnitInterval) {
    for (DistanceMetric m : kMetrics) {
        for (int i = 0; i < 20000; ++i) {
            const Vec3 p = point(i, 1000.0f);
            const CellularDistances d = cellular_3d(p, 5, m);
            ASSERT_LE(0.0f, d.f1);
            ASSERT_LE(d.f1, d.f2);
            ASSERT_LE(d.f2, d.f3);
            ASSERT_TRUE(std::isfinite(d.f3));
            const float c = cellular_combination(d);
            ASSERT_GE(c, 0.0f);
            ASSERT_LE(c, 1.0f);
        }
    }
}

// Per point, Chebyshev ≤ Euclidean ≤ Manhattan, so the same holds for the nearest distances.
TEST(Cellular, MetricsAreOrdered) {
    for (int i = 0; i < 5000; ++i) {
        const Vec3 p = point(i, 100.0f);
        const float e = cellular_3d(p, 1, DistanceMetric::Euclidean).f1;
        EXPECT_LE(cellular_3d(p, 1, DistanceMetric::Chebyshev).f1, e);
        EXPECT_LE(e, cellular_3d(p, 1, DistanceMetric::Manhattan).f1);
    }
}

TEST(Cellular, ZeroAtAFeaturePointWhichLiesInItsCell) {
    for (int i = -5; i <= 5; ++i) {
        const Vec3 f = cellular_feature_3d(i, -i, 2 * i, 8);
        EXPECT_EQ(floor_to_int(f.x), i);
        EXPECT_EQ(floor_to_int(f.y), -i);
        EXPECT_EQ(floor_to_int(f.z), 2 * i);
        const CellularDistances d = cellular_3d(f, 8);
        EXPECT_EQ(d.f1, 0.0f);
        EXPECT_EQ(cellular_combination(d), 0.0f);
        EXPECT_EQ(d.cell_id, hash_3d(i, -i, 2 * i, 8));
    }
}

// The k-th nearest distance is 1-Lipschitz: a step δ along x changes F1, F2, F3 by at most δ in
// every metric here. Swept across 0 (the printed int() truncation broke the lattice there).
TEST(Cellular, ContinuousAcrossNegativeCoordinates) {
    const float step = 1e-3f;
    for (DistanceMetric m : kMetrics) {
        CellularDistances prev = cellular_3d(Vec3(-4.0f, 0.3f, -0.6f), 3, m);
        for (int i = -3999; i <= 4000; ++i) {
            const Vec3 p(i * step, 0.3f, -0.6f);
            const CellularDistances d = cellular_3d(p, 3, m);
            ASSERT_LE(std::fabs(d.f1 - prev.f1), step * 1.001f + 1e-6f) << p.x;
            ASSERT_LE(std::fabs(d.f2 - prev.f2), step * 1.001f + 1e-6f) << p.x;
            ASSERT_LE(std::fabs(d.f3 - prev.f3), step * 1.001f + 1e-6f) << p.x;
            prev = d;
        }
        CellularDistances p2 = cellular_2d(-4.0f, 0.5f, 3, m);
        for (int i = -3999; i <= 4000; ++i) {
            const CellularDistances d = cellular_2d(i * step, 0.5f, 3, m);
            ASSERT_LE(std::fabs(d.f1 - p2.f1), step * 1.001f + 1e-6f) << i * step;
            ASSERT_LE(std::fabs(d.f3 - p2.f3), step * 1.001f + 1e-6f) << i * step;
            p2 = d;
        }
    }
}

// Golden F1, F2, F3 and cell id from tests/shading/noise_golden.py (an independent brute-force
// reimplementation in double over the 5×5×5 block): a change to the feature points' hashing
// moves them. Dyadic points, exact in float; distances to ~1e-6 (float against double).
TEST(Cellular, GoldenValuesOfAnIndependentImplementation) {
    struct Golden {
        Vec3 p;
        double f1, f2, f3;
        uint32_t cell_id;
    };
    const Golden golden[] = {
        {Vec3(0.375f, -1.25f, 2.625f), 0.212751455, 0.625372642, 0.708163585, 1868766098u},
        {Vec3(-3.5f, 0.125f, 7.75f), 0.412361056, 0.792763665, 0.858252257, 3018456540u},
        {Vec3(10.0625f, -20.5f, 0.8125f), 0.548254606, 0.613209506, 0.705116385, 3459062289u},
    };
    for (const Golden& g : golden) {
        const CellularDistances d = cellular_3d(g.p, 9);
        EXPECT_NEAR(d.f1, g.f1, 1e-5) << g.p.x;
        EXPECT_NEAR(d.f2, g.f2, 1e-5) << g.p.x;
        EXPECT_NEAR(d.f3, g.f3, 1e-5) << g.p.x;
        EXPECT_EQ(d.cell_id, g.cell_id) << g.p.x;
    }
}

// The same (point, seed) gives the same bits on every call, whatever was evaluated in between
// (no hidden state), and the seed selects another pattern.
TEST(Cellular, RepeatableForASeedAndDifferentAcrossSeeds) {
    const int n = 2000;
    std::vector<CellularDistances> first(n);
    for (int i = 0; i < n; ++i) first[i] = cellular_3d(point(i, 50.0f), 9);
    for (int i = n - 1; i >= 0; --i) {  // again, in reverse order, after another seed
        cellular_3d(point(i, 50.0f), 10);
        const CellularDistances again = cellular_3d(point(i, 50.0f), 9);
        ASSERT_EQ(again.f1, first[i].f1) << i;
        ASSERT_EQ(again.f2, first[i].f2) << i;
        ASSERT_EQ(again.f3, first[i].f3) << i;
        ASSERT_EQ(again.cell_id, first[i].cell_id) << i;
    }
    int differ = 0;
    for (int i = 0; i < 1000; ++i) differ += cellular_3d(point(i, 50.0f), 10).f1 != first[i].f1;
    EXPECT_GE(differ, 990);
}

}  // namespace
}  // namespace rayo
