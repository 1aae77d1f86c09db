#pragma once
// The cells of a regular grid that a ray crosses, in order (Amanatides & Woo 1987, "A fast voxel
// traversal algorithm for ray tracing"): the directional DDA the height field (2-D, over its
// cells and blocks of cells) and the voxel grid (3-D) walk. Cells are unit cubes in grid
// coordinates; t is the caller's ray parameter, so the grid's scale may differ per axis.
#include <algorithm>
#include <cmath>
#include <limits>

namespace rayo {

// Visits the cells c (c[a] in [lo[a], hi[a]]) that the segment o + t·d, t in [t0, t1],
// crosses, in order, as visit(c, ta, tb) with the segment's t interval in the cell. Stops and
// returns true when visit returns true. The first cell is the one holding o + t0·d, clamped
// into the range; the t at which the segment leaves a cell is computed from the cell index
// (not accumulated), so long walks do not drift.
template <int N, typename Visit>
bool walk_grid(const float (&o)[N], const float (&d)[N], float t0, float t1, const int (&lo)[N],
               const int (&hi)[N], Visit&& visit) {
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    int cell[N], step[N];
    float inverse[N], exit[N];
    for (int a = 0; a < N; ++a) {
        cell[a] = std::clamp(static_cast<int>(std::floor(o[a] + d[a] * t0)), lo[a], hi[a]);
        step[a] = d[a] > 0.0f ? 1 : d[a] < 0.0f ? -1 : 0;
        inverse[a] = 1.0f / d[a];
        exit[a] = step[a] ? (float(cell[a] + (step[a] > 0)) - o[a]) * inverse[a] : kInfinity;
    }
    float t = t0;
    for (;;) {
        int axis = 0;
        for (int a = 1; a < N; ++a) {
            if (exit[a] < exit[axis]) axis = a;
        }
        const float t_next = std::min(exit[axis], t1);
        if (visit(cell, t, std::max(t, t_next))) return true;
        if (t_next >= t1) return false;
        cell[axis] += step[axis];
        if (cell[axis] < lo[axis] || cell[axis] > hi[axis]) return false;
        t = std::max(t, exit[axis]);
        exit[axis] = (float(cell[axis] + (step[axis] > 0)) - o[axis]) * inverse[axis];
    }
}

}  // namespace rayo
