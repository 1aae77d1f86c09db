// The piecewise-constant distributions of core/piecewise_constant.h: samples fall in each cell
// in proportion to its weight (a chi-square-style histogram check), never in a cell of weight
// 0, the reported density is the cell's weight over the mean weight, and the 2-D distribution's
// density integrates to 1 over the square.
#include "core/piecewise_constant.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/sampling.h"

namespace rayo {
namespace {

TEST(PiecewiseConstant, SamplesFollowTheWeightsAndSkipEmptyCells) {
    const std::vector<float> weights = {1.0f, 0.0f, 3.0f, 0.5f, 0.0f, 2.5f};
    const PiecewiseConstant1D d(weights);
    EXPECT_DOUBLE_EQ(d.total(), 7.0);
    const int n = 1 << 18;
    std::vector<int> histogram(weights.size(), 0);
    for (int i = 0; i < n; ++i) {
        float density = 0.0f;
        size_t cell = 0;
        const float x = d.sample(sample_uniform(1, 2, i, 0), density, cell);
        ASSERT_GE(x, 0.0f);
        ASSERT_LT(x, 1.0f);
        ASSERT_EQ(cell, static_cast<size_t>(x * weights.size()));
        ASSERT_GT(weights[cell], 0.0f) << "sampled an empty cell";
        ASSERT_FLOAT_EQ(density, weights[cell] * 6.0f / 7.0f);
        EXPECT_EQ(d.density(x), density);
        ++histogram[cell];
    }
    for (size_t c = 0; c < weights.size(); ++c) {
        const double expected = n * weights[c] / 7.0;
        // Binomial standard deviation; 5 of them.
        EXPECT_NEAR(histogram[c], expected, 5.0 * std::sqrt(expected + 1.0)) << "cell " << c;
    }
}

TEST(PiecewiseConstant, AllZeroWeightsAreUniform) {
    const PiecewiseConstant1D d(std::vector<float>(4, 0.0f));
    float density = 0.0f;
    size_t cell = 9;
    EXPECT_FLOAT_EQ(d.sample(0.6f, density, cell), 0.6f);
    EXPECT_EQ(cell, 2u);
    EXPECT_EQ(density, 1.0f);
}

TEST(PiecewiseConstant, TheSquaresDensityIntegratesToOneAndMatchesItsSamples) {
    const size_t columns = 5, rows = 3;
    std::vector<float> weights(columns * rows);
    for (size_t i = 0; i < weights.size(); ++i) weights[i] = static_cast<float>((i * 7) % 4);
    const PiecewiseConstant2D d(weights, columns, rows);
    double integral = 0.0;
    const int grid = 300;  // a multiple of both sizes: every probe inside one cell
    for (int j = 0; j < grid; ++j) {
        for (int i = 0; i < grid; ++i) {
            integral += d.density((i + 0.5f) / grid, (j + 0.5f) / grid);
        }
    }
    EXPECT_NEAR(integral / (grid * grid), 1.0, 1e-4);
    for (int i = 0; i < 4096; ++i) {
        float x, y, density;
        d.sample(sample_uniform(3, 4, i, 0), sample_uniform(3, 4, i, 1), x, y, density);
        const size_t cell =
            static_cast<size_t>(y * rows) * columns + static_cast<size_t>(x * columns);
        ASSERT_GT(weights[cell], 0.0f);
        EXPECT_FLOAT_EQ(density, d.density(x, y));
    }
}

}  // namespace
}  // namespace rayo
