// Tests of the stateless per-pixel random numbers (core/sampling.h): determinism, range,
// uniformity (mean and chi-square), and the stratified sub-pixel offsets.
#include "core/sampling.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

namespace rayo {
namespace {

TEST(Sampling, SameInputsGiveTheSameValue) {
    // Stateless: the value is a function of (x, y, sample, dimension, frame) only, whatever was
    // drawn before (docs/architecture.md: output must not depend on thread count or tile order).
    const float first = sample_uniform(17, 42, 3, 1, 0);
    for (int i = 0; i < 100; ++i) sample_uniform(uint32_t(i), 7, 0, 0);
    EXPECT_EQ(sample_uniform(17, 42, 3, 1, 0), first);
    EXPECT_EQ(sample_uniform(17, 42, 3, 1), first);  // frame defaults to 0
    // Each input changes the value.
    EXPECT_NE(sample_uniform(18, 42, 3, 1, 0), first);
    EXPECT_NE(sample_uniform(17, 43, 3, 1, 0), first);
    EXPECT_NE(sample_uniform(17, 42, 4, 1, 0), first);
    EXPECT_NE(sample_uniform(17, 42, 3, 2, 0), first);
    EXPECT_NE(sample_uniform(17, 42, 3, 1, 1), first);
    // Swapping x and y is a different pixel.
    EXPECT_NE(sample_uniform(42, 17, 3, 1, 0), first);
    // The hash is a fixed function (lowbias32): the same 32-bit input, the same output.
    EXPECT_EQ(hash_u32(12345u), hash_u32(12345u));
    EXPECT_NE(hash_u32(12345u), hash_u32(12346u));
}

// Chi-square statistic of `values` in `bins` equal bins of [0, 1).
double chi_square(const std::vector<float>& values, int bins) {
    std::vector<int> counts(bins, 0);
    for (float v : values) counts[std::min(bins - 1, int(v * float(bins)))]++;
    const double expected = double(values.size()) / bins;
    double chi2 = 0.0;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    return chi2;
}

// The 99.9% quantile of chi-square with 19 degrees of freedom is 43.82; with 99, 148.23.
constexpr double kChi2Critical19 = 43.82;
constexpr double kChi2Critical99 = 148.23;

void check_stream(const std::vector<float>& values) {
    double sum = 0.0;
    for (float v : values) {
        ASSERT_GE(v, 0.0f);
        ASSERT_LT(v, 1.0f);
        sum += v;
    }
    // Mean of U[0,1) is 0.5 with standard error √(1/12/1e5) = 0.00091: 0.004 is 4.4 sigma.
    EXPECT_NEAR(sum / double(values.size()), 0.5, 0.004);
    EXPECT_LT(chi_square(values, 20), kChi2Critical19);
}

TEST(Sampling, UniformOverPixels) {
    // 1e5 samples over a 400×250 block of pixels, sample 0, dimension 0.
    // Measured: mean 0.49902, chi-square (19 dof) 10.1.
    std::vector<float> values;
    for (uint32_t y = 0; y < 250; ++y)
        for (uint32_t x = 0; x < 400; ++x) values.push_back(sample_uniform(x, y, 0, 0));
    ASSERT_EQ(values.size(), 100000u);
    check_stream(values);
}

TEST(Sampling, UniformOverSamplesAndDimensions) {
    // One pixel: 1e5 sample indices (dimension 1), 1e5 dimensions (sample 0), 1e5 frames.
    // Measured: means 0.50147, 0.49976, 0.50088; chi-square (19 dof) 14.0, 9.2, 18.5.
    std::vector<float> by_sample, by_dimension, by_frame;
    for (uint32_t i = 0; i < 100000; ++i) {
        by_sample.push_back(sample_uniform(5, 9, i, 1));
        by_dimension.push_back(sample_uniform(5, 9, 0, i));
        by_frame.push_back(sample_uniform(5, 9, 0, 0, i));
    }
    check_stream(by_sample);
    check_stream(by_dimension);
    check_stream(by_frame);
}

TEST(Sampling, DimensionsAreIndependent) {
    // Pairs (dimension 0, dimension 1) of 1e5 pixels in a 10×10 grid of cells: chi-square with
    // 99 degrees of freedom, as a correlated pair would crowd some cells. Measured: 88.8.
    std::array<int, 100> counts{};
    for (uint32_t y = 0; y < 250; ++y) {
        for (uint32_t x = 0; x < 400; ++x) {
            const int i = std::min(9, int(sample_uniform(x, y, 0, 0) * 10.0f));
            const int j = std::min(9, int(sample_uniform(x, y, 0, 1) * 10.0f));
            counts[i * 10 + j]++;
        }
    }
    double chi2 = 0.0;
    for (int c : counts) chi2 += (c - 1000.0) * (c - 1000.0) / 1000.0;
    EXPECT_LT(chi2, kChi2Critical99);
}

TEST(Sampling, OnePixelSampleGoesThroughTheCentre) {
    for (uint32_t x : {0u, 3u, 1000u}) {
        const PixelOffset o = stratified_offset(x, 2 * x + 1, 0, 1);
        EXPECT_EQ(o.dx, 0.0f);
        EXPECT_EQ(o.dy, 0.0f);
    }
}

// For each pixel, the stratum (column, row) of each of its `spp` samples must be distinct and
// cover the columns × rows grid exactly once.
void check_strata(uint32_t spp, uint32_t columns, uint32_t rows) {
    for (uint32_t y = 0; y < 40; ++y) {
        for (uint32_t x = 0; x < 40; ++x) {
            std::vector<int> hits(spp, 0);
            for (uint32_t s = 0; s < spp; ++s) {
                const PixelOffset o = stratified_offset(x, y, s, spp);
                ASSERT_GE(o.dx, -0.5f);
                ASSERT_LT(o.dx, 0.5f);
                ASSERT_GE(o.dy, -0.5f);
                ASSERT_LT(o.dy, 0.5f);
                const int column = int(std::floor((o.dx + 0.5f) * float(columns)));
                const int row = int(std::floor((o.dy + 0.5f) * float(rows)));
                ASSERT_GE(column, 0);
                ASSERT_LT(column, int(columns));
                ASSERT_GE(row, 0);
                ASSERT_LT(row, int(rows));
                hits[row * columns + column]++;
            }
            for (uint32_t k = 0; k < spp; ++k) {
                EXPECT_EQ(hits[k], 1) << "pixel " << x << "," << y << " stratum " << k;
            }
        }
    }
}

TEST(Sampling, FourSamplesOnePerStratum) {
    // spp = 4: columns = largest divisor of 4 not above √4 = 2, rows = 2.
    check_strata(4, 2, 2);
}

TEST(Sampling, SixSamplesOnePerStratum) {
    // spp = 6: columns = largest divisor of 6 not above √6 ≈ 2.45 = 2, rows = 3.
    check_strata(6, 2, 3);
}

TEST(Sampling, NineAndTwoSamplesOnePerStratum) {
    check_strata(9, 3, 3);  // 3 × 3
    check_strata(2, 1, 2);  // columns = 1, rows = 2
}

TEST(Sampling, OffsetsStayBelowHalfAtTheLargestJitter) {
    // sample_uniform can return 1 − 2^−24 (all 24 bits set). In float, column + jitter then
    // rounds up to column + 1 (e.g. 1 + (1 − 2^−24) = 2 − 2^−24 rounds to 2), so the offset
    // becomes exactly 0.5, outside [−0.5, 0.5) and in the next pixel's stratum. These inputs,
    // found by a search over 4096² pixels, have that jitter in a column/row 1 of spp = 4.
    ASSERT_EQ(sample_uniform(180, 178, 3, 1), 1.0f - 1.0f / 16777216.0f);
    ASSERT_EQ(sample_uniform(3355, 1616, 1, 0), 1.0f - 1.0f / 16777216.0f);
    const PixelOffset a = stratified_offset(180, 178, 3, 4);  // column 1, row 1: dy
    EXPECT_LT(a.dy, 0.5f);
    EXPECT_GE(a.dy, 0.0f);
    const PixelOffset b = stratified_offset(3355, 1616, 1, 4);  // column 1, row 0: dx
    EXPECT_LT(b.dx, 0.5f);
    EXPECT_GE(b.dx, 0.0f);
}

TEST(Sampling, ConcentricDiskMapsKnownPoints) {
    // Shirley–Chiu: the square's centre to the disk's, edge midpoints and corners to the rim.
    const auto near = [](glm::vec2 a, float x, float y) {
        EXPECT_NEAR(a.x, x, 1e-6f) << a.x << ", " << a.y;
        EXPECT_NEAR(a.y, y, 1e-6f) << a.x << ", " << a.y;
    };
    near(concentric_disk(glm::vec2(0.5f, 0.5f)), 0.0f, 0.0f);
    near(concentric_disk(glm::vec2(1.0f, 0.5f)), 1.0f, 0.0f);
    near(concentric_disk(glm::vec2(0.5f, 1.0f)), 0.0f, 1.0f);
    near(concentric_disk(glm::vec2(0.0f, 0.5f)), -1.0f, 0.0f);
    near(concentric_disk(glm::vec2(0.5f, 0.0f)), 0.0f, -1.0f);
    const float h = std::sqrt(0.5f);
    near(concentric_disk(glm::vec2(1.0f, 1.0f)), h, h);  // corner: 45° on the rim
    near(concentric_disk(glm::vec2(0.0f, 0.0f)), -h, -h);
    // A square ring of half-side r goes to the circle of radius r.
    for (float t : {0.1f, 0.3f, 0.55f, 0.8f}) {
        EXPECT_NEAR(glm::length(concentric_disk(glm::vec2(0.75f, 0.5f + t * 0.25f))), 0.5f, 1e-6f);
    }
}

TEST(Sampling, ConcentricDiskPreservesArea) {
    // Equal areas of the square go to equal areas of the disk: a 64×64 grid of cell centres puts
    // a quarter of its points inside radius 1/2 and 9/16 inside 3/4, and none outside radius 1.
    int inside_half = 0, inside_three_quarters = 0, outside = 0;
    constexpr int kGrid = 64;
    for (int j = 0; j < kGrid; ++j) {
        for (int i = 0; i < kGrid; ++i) {
            const float r =
                glm::length(concentric_disk(glm::vec2((i + 0.5f) / kGrid, (j + 0.5f) / kGrid)));
            inside_half += r < 0.5f;
            inside_three_quarters += r < 0.75f;
            outside += r > 1.0f;
        }
    }
    EXPECT_NEAR(inside_half / double(kGrid * kGrid), 0.25, 0.005);
    EXPECT_NEAR(inside_three_quarters / double(kGrid * kGrid), 0.5625, 0.005);
    EXPECT_EQ(outside, 0);
}

}  // namespace
}  // namespace rayo
