#pragma once
// Piecewise-constant distributions on [0,1) and [0,1)² sampled by inverting their cumulative
// sums (the standard construction: Pharr, Jakob & Humphreys 2016, §13.6.5; here for the
// environment light's importance sampling, shading/environment_light.h). Weights must be finite
// and non-negative; cells of weight 0 are never sampled and have density 0.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace rayo {

class PiecewiseConstant1D {
  public:
    PiecewiseConstant1D() = default;
    explicit PiecewiseConstant1D(std::vector<float> weights) : m_weights(std::move(weights)) {
        m_cdf.resize(m_weights.size() + 1, 0.0);
        for (size_t i = 0; i < m_weights.size(); ++i) m_cdf[i + 1] = m_cdf[i] + m_weights[i];
        m_total = m_cdf.back();
    }

    size_t size() const { return m_weights.size(); }
    // The sum of the weights (the integral times size()).
    double total() const { return m_total; }

    // x ∈ [0,1) distributed as the weights for uniform u ∈ [0,1), with its density and cell.
    // All-zero weights: uniform.
    float sample(float u, float& density, size_t& cell) const {
        const size_t n = m_weights.size();
        if (!(m_total > 0.0)) {
            cell = std::min(static_cast<size_t>(u * static_cast<float>(n)), n - 1);
            density = 1.0f;
            return u;
        }
        const double target = static_cast<double>(u) * m_total;
        // The last cell whose running sum below it is <= target, skipping empty cells.
        cell = static_cast<size_t>(std::upper_bound(m_cdf.begin(), m_cdf.end(), target) -
                                   m_cdf.begin());
        cell = std::min(std::max<size_t>(cell, 1), n) - 1;
        while (m_weights[cell] <= 0.0f && cell + 1 < n) ++cell;
        const double within = (target - m_cdf[cell]) / m_weights[cell];
        density = static_cast<float>(m_weights[cell] * static_cast<double>(n) / m_total);
        const double x =
            (static_cast<double>(cell) + std::clamp(within, 0.0, 1.0)) / static_cast<double>(n);
        return std::min(static_cast<float>(x), 0x1.fffffep-1f);
    }

    // The density at x ∈ [0,1).
    float density(float x) const {
        const size_t n = m_weights.size();
        if (!(m_total > 0.0)) return 1.0f;
        const size_t cell = std::min(static_cast<size_t>(std::max(x, 0.0f) * n), n - 1);
        return static_cast<float>(m_weights[cell] * static_cast<double>(n) / m_total);
    }

  private:
    std::vector<float> m_weights;
    std::vector<double> m_cdf;  // running sums, m_cdf[0] = 0, size() + 1 entries
    double m_total = 0.0;
};

// A distribution on [0,1)² given by `columns` × `rows` weights, row by row: the marginal picks
// the row (y), the row's own conditional the column (x).
class PiecewiseConstant2D {
  public:
    PiecewiseConstant2D() = default;
    PiecewiseConstant2D(const std::vector<float>& weights, size_t columns, size_t rows) {
        std::vector<float> row_totals(rows);
        m_rows.reserve(rows);
        for (size_t y = 0; y < rows; ++y) {
            m_rows.emplace_back(std::vector<float>(weights.begin() + y * columns,
                                                   weights.begin() + (y + 1) * columns));
            row_totals[y] = static_cast<float>(m_rows.back().total());
        }
        m_marginal = PiecewiseConstant1D(std::move(row_totals));
    }

    bool empty() const { return m_rows.empty(); }

    // (x, y) ∈ [0,1)² for uniform u, and its density with respect to area in [0,1)².
    void sample(float ux, float uy, float& x, float& y, float& density) const {
        float row_density = 0.0f, column_density = 0.0f;
        size_t row = 0, column = 0;
        y = m_marginal.sample(uy, row_density, row);
        x = m_rows[row].sample(ux, column_density, column);
        density = row_density * column_density;
    }

    float density(float x, float y) const {
        const size_t rows = m_rows.size();
        const size_t row = std::min(static_cast<size_t>(std::max(y, 0.0f) * rows), rows - 1);
        return m_marginal.density(y) * m_rows[row].density(x);
    }

  private:
    std::vector<PiecewiseConstant1D> m_rows;
    PiecewiseConstant1D m_marginal;
};

}  // namespace rayo
