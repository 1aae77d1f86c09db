#pragma once
// Worley's cellular noise (seed 003 ch. 3, "Mapa celular"): one hashed feature point per unit
// cell; F1 <= F2 <= F3 are the distances to the three nearest, under a choice of metric.
// The search is exact: the 3×3 (3-D: 3×3×3) block, then outer rings only while they can hold
// a closer point (the seed's 3×3 alone can miss F2/F3, its figs. 3.10-3.11).
#include <cstdint>

#include "core/math.h"

namespace rayo {

enum class DistanceMetric {
    Euclidean,
    Manhattan,  // |dx| + |dy| + |dz|
    Chebyshev,  // max(|dx|, |dy|, |dz|)
};

struct CellularDistances {
    float f1 = 0.0f, f2 = 0.0f, f3 = 0.0f;
    uint32_t cell_id = 0;  // hash of the nearest feature's cell: a stable per-cell random id
};

// The feature point of lattice cell (x, y[, z]) for `seed`, inside that cell.
Vec3 cellular_feature_3d(int32_t x, int32_t y, int32_t z, uint32_t seed);
void cellular_feature_2d(int32_t x, int32_t y, uint32_t seed, float& fx, float& fy);

CellularDistances cellular_3d(const Vec3& p, uint32_t seed,
                              DistanceMetric metric = DistanceMetric::Euclidean);
CellularDistances cellular_2d(float x, float y, uint32_t seed,
                              DistanceMetric metric = DistanceMetric::Euclidean);

// seed 003's combination 2·F1/(F2 + F3), in [0, 1]: 0 at a feature point, near 1 on the cell
// edges and brightest at the corners where three cells meet.
inline float cellular_combination(const CellularDistances& d) {
    const float denominator = d.f2 + d.f3;
    return denominator > 0.0f ? glm::clamp(2.0f * d.f1 / denominator, 0.0f, 1.0f) : 0.0f;
}

}  // namespace rayo
