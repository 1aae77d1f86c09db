#pragma once
// An iso-surface of a field sampled on a lattice, as Embree triangles: marching tetrahedra, the
// marching cubes family (Lorensen & Cline 1987) with each lattice cube split into six
// tetrahedra around its main diagonal (a decomposition neighbouring cubes agree on), which needs
// no 256-case table and has no ambiguous cases: a tetrahedron with one or three corners inside
// gets one triangle, with two a quad (two triangles). Vertices lie on the cube edges where the
// linear interpolation of the samples crosses zero, one per edge (shared by the triangles around
// it). The tessellated forms of blobs (core/shapes/blob_mesh.h) and of voxel grids
// (core/shapes/voxel_grid.h).
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

// Triangles wound counter-clockwise seen from outside, with vertex normals from `outward`,
// every triangle of `material`.
TriangleMesh marching_tetrahedra(const SampledField& field, uint32_t material,
                                 const std::string& name);

}  // namespace rayo
