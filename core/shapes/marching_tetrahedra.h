#pragma once
// An iso-surface of a field sampled on a lattice, as Embree triangles: marching tetrahedra, the
// marching cubes family (Lorensen & Cline 1987) with each lattice cube split into six
// tetrahedra around its main diagonal (a decomposition neighbouring cubes agree on), which needs
// no 256-case table and has no ambiguous cases: a tetrahedron with one or three corners inside
// gets one triangle, with two a quad (two triangles). Vertices lie on the cube edges where the
// linear interpolation of the samples crosses zero, one per edge (shared by the triangles around
// it). The tessellated forms of blobs (core/shapes/blob_mesh.h) and of voxel grids
// (core/shapes/voxel_grid.h).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/shapes/mesh.h"

namespace rayo {

struct SampledField {
    DVec3 lower{0.0};  // the lattice point (0, 0, 0)
    DVec3 cell{1.0};   // lattice spacing along each axis
    int counts[3] = {0, 0, 0};
    // counts[0]·counts[1]·counts[2] samples, x fastest; inside where > 0, the surface at 0.
    std::vector<double> samples;
    // The unit outward normal at a surface point (e.g. −∇F / |∇F|).
    std::function<Vec3(const DVec3&)> outward;
};

// The cube's corners (bit 0: +x, bit 1: +y, bit 2: +z) and its six tetrahedra around the
// diagonal 0–7: each runs 0 → 7 through two corners that differ in one more axis.
constexpr int kCubeTetrahedra[6][4] = {{0, 7, 1, 3}, {0, 7, 3, 2}, {0, 7, 2, 6},
                                       {0, 7, 6, 4}, {0, 7, 4, 5}, {0, 7, 5, 1}};

// The triangles marching_tetrahedra() makes of a lattice of counts[0]·counts[1]·counts[2]
// samples g(i, j, k) (inside where > 0) before it drops degenerate ones (a corner exactly on
// the surface): an upper bound on its triangle count without building the mesh. A tetrahedron
// with one or three corners inside gets one triangle, with two a quad.
template <typename G>
size_t marching_tetrahedra_triangles(const int counts[3], G&& g) {
    size_t triangles = 0;
    for (int k = 0; k + 1 < counts[2]; ++k) {
        for (int j = 0; j + 1 < counts[1]; ++j) {
            for (int i = 0; i + 1 < counts[0]; ++i) {
                bool in[8];
                int inside = 0;
                for (int c = 0; c < 8; ++c) {
                    in[c] = g(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)) > 0.0;
                    inside += in[c];
                }
                if (inside == 0 || inside == 8) continue;
                for (const auto& tet : kCubeTetrahedra) {
                    const int n = in[tet[0]] + in[tet[1]] + in[tet[2]] + in[tet[3]];
                    triangles += n == 2 ? 2 : (n == 1 || n == 3) ? 1 : 0;
                }
            }
        }
    }
    return triangles;
}

// Triangles wound counter-clockwise seen from outside, with vertex normals from `outward`,
// every triangle of `material`.
TriangleMesh marching_tetrahedra(const SampledField& field, uint32_t material,
                                 const std::string& name);

}  // namespace rayo
