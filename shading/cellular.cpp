#include "shading/cellular.h"

#include <cmath>
#include <limits>

#include "shading/noise.h"

namespace rayo {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Distances are compared in "key" space: squared for Euclidean (no sqrt per candidate).
template <DistanceMetric M>
inline float key(float dx, float dy, float dz) {
    if constexpr (M == DistanceMetric::Euclidean) {
        return dx * dx + dy * dy + dz * dz;
    } else if constexpr (M == DistanceMetric::Manhattan) {
        return std::fabs(dx) + std::fabs(dy) + std::fabs(dz);
    } else {
        return glm::max(std::fabs(dx), glm::max(std::fabs(dy), std::fabs(dz)));
    }
}

template <DistanceMetric M>
inline float key_to_distance(float k) {
    if constexpr (M == DistanceMetric::Euclidean) {
        return std::sqrt(k);
    } else {
        return k;
    }
}

// Keeps the three smallest keys (seed 003's "tercera fase").
struct Nearest3 {
    float k[3] = {kInfinity, kInfinity, kInfinity};
    uint32_t id = 0;

    void insert(float d, uint32_t cell) {
        if (d < k[0]) {
            k[2] = k[1];
            k[1] = k[0];
            k[0] = d;
            id = cell;
        } else if (d < k[1]) {
            k[2] = k[1];
            k[1] = d;
        } else if (d < k[2]) {
            k[2] = d;
        }
    }
};

// Lower bound of the distance from a point at fraction f in its cell to any point of the cell at
// offset o along one axis: the empty cells in between plus the way to the near wall.
inline float axis_gap(int o, float f) {
    if (o < 0) return static_cast<float>(-o - 1) + f;
    if (o > 0) return static_cast<float>(o - 1) + (1.0f - f);
    return 0.0f;
}

// The feature point of a cell from the cell's lattice hash h0: three independent 24-bit offsets
// (seed 003: IntNoise per cell, one point per cell).
inline Vec3 feature_3d(int32_t x, int32_t y, int32_t z, uint32_t h0) {
    const uint32_t h1 = hash_u32(h0 ^ 0x68e31da4u);
    const uint32_t h2 = hash_u32(h1 ^ 0xb5297a4du);
    return Vec3(static_cast<float>(x) + unit_float(h0), static_cast<float>(y) + unit_float(h1),
                static_cast<float>(z) + unit_float(h2));
}

inline void feature_2d(int32_t x, int32_t y, uint32_t h0, float& fx, float& fy) {
    fx = static_cast<float>(x) + unit_float(h0);
    fy = static_cast<float>(y) + unit_float(hash_u32(h0 ^ 0x68e31da4u));
}

template <DistanceMetric M>
CellularDistances search_3d(const Vec3& p, uint32_t seed) {
    const int32_t cx = floor_to_int(p.x), cy = floor_to_int(p.y), cz = floor_to_int(p.z);
    const Vec3 f(p.x - static_cast<float>(cx), p.y - static_cast<float>(cy),
                 p.z - static_cast<float>(cz));
    Nearest3 best;
    auto visit = [&](int ox, int oy, int oz) {
        const int32_t x = cx + ox, y = cy + oy, z = cz + oz;
        const uint32_t h = hash_3d(x, y, z, seed);
        const Vec3 q = feature_3d(x, y, z, h);
        best.insert(key<M>(q.x - p.x, q.y - p.y, q.z - p.z), h);
    };
    // The seed's neighbourhood, fixed: the whole 3×3×3 block around the cell.
    for (int oz = -1; oz <= 1; ++oz) {
        for (int oy = -1; oy <= 1; ++oy) {
            for (int ox = -1; ox <= 1; ++ox) visit(ox, oy, oz);
        }
    }
    // Outer rings while they may hold a point closer than F3. Every metric here is at least the
    // largest axis gap, so the gaps bound the ring and each cell from below.
    const float near_wall = glm::min(glm::min(glm::min(f.x, 1.0f - f.x), glm::min(f.y, 1.0f - f.y)),
                                     glm::min(f.z, 1.0f - f.z));
    for (int r = 2;; ++r) {
        const float ring_gap = static_cast<float>(r - 1) + near_wall;
        if (key<M>(ring_gap, 0.0f, 0.0f) >= best.k[2]) break;
        for (int oz = -r; oz <= r; ++oz) {
            for (int oy = -r; oy <= r; ++oy) {
                for (int ox = -r; ox <= r; ++ox) {
                    if (std::abs(ox) != r && std::abs(oy) != r && std::abs(oz) != r) continue;
                    const float gap =
                        key<M>(axis_gap(ox, f.x), axis_gap(oy, f.y), axis_gap(oz, f.z));
                    if (gap < best.k[2]) visit(ox, oy, oz);
                }
            }
        }
    }
    return {key_to_distance<M>(best.k[0]), key_to_distance<M>(best.k[1]),
            key_to_distance<M>(best.k[2]), best.id};
}

template <DistanceMetric M>
CellularDistances search_2d(float px, float py, uint32_t seed) {
    const int32_t cx = floor_to_int(px), cy = floor_to_int(py);
    const float fx = px - static_cast<float>(cx), fy = py - static_cast<float>(cy);
    Nearest3 best;
    auto visit = [&](int ox, int oy) {
        const uint32_t h = hash_2d(cx + ox, cy + oy, seed);
        float qx, qy;
        feature_2d(cx + ox, cy + oy, h, qx, qy);
        best.insert(key<M>(qx - px, qy - py, 0.0f), h);
    };
    // seed 003 fixed: the neighbour of (i, j) is cell (cx + i, cy + j), the full 3×3 block.
    for (int oy = -1; oy <= 1; ++oy) {
        for (int ox = -1; ox <= 1; ++ox) visit(ox, oy);
    }
    const float near_wall = glm::min(glm::min(fx, 1.0f - fx), glm::min(fy, 1.0f - fy));
    for (int r = 2;; ++r) {
        if (key<M>(static_cast<float>(r - 1) + near_wall, 0.0f, 0.0f) >= best.k[2]) break;
        for (int oy = -r; oy <= r; ++oy) {
            for (int ox = -r; ox <= r; ++ox) {
                if (std::abs(ox) != r && std::abs(oy) != r) continue;
                if (key<M>(axis_gap(ox, fx), axis_gap(oy, fy), 0.0f) < best.k[2]) visit(ox, oy);
            }
        }
    }
    return {key_to_distance<M>(best.k[0]), key_to_distance<M>(best.k[1]),
            key_to_distance<M>(best.k[2]), best.id};
}

}  // namespace

Vec3 cellular_feature_3d(int32_t x, int32_t y, int32_t z, uint32_t seed) {
    return feature_3d(x, y, z, hash_3d(x, y, z, seed));
}

void cellular_feature_2d(int32_t x, int32_t y, uint32_t seed, float& fx, float& fy) {
    feature_2d(x, y, hash_2d(x, y, seed), fx, fy);
}

CellularDistances cellular_3d(const Vec3& p, uint32_t seed, DistanceMetric metric) {
    switch (metric) {
        case DistanceMetric::Manhattan:
            return search_3d<DistanceMetric::Manhattan>(p, seed);
        case DistanceMetric::Chebyshev:
            return search_3d<DistanceMetric::Chebyshev>(p, seed);
        case DistanceMetric::Euclidean:
            break;
    }
    return search_3d<DistanceMetric::Euclidean>(p, seed);
}

CellularDistances cellular_2d(float x, float y, uint32_t seed, DistanceMetric metric) {
    switch (metric) {
        case DistanceMetric::Manhattan:
            return search_2d<DistanceMetric::Manhattan>(x, y, seed);
        case DistanceMetric::Chebyshev:
            return search_2d<DistanceMetric::Chebyshev>(x, y, seed);
        case DistanceMetric::Euclidean:
            break;
    }
    return search_2d<DistanceMetric::Euclidean>(x, y, seed);
}

}  // namespace rayo
