#pragma once
// A blob (core/shapes/blob.h) tessellated for Embree: its mesh form (`"method": "mesh"`,
// docs/shape-methods.md) and the tessellated form the analytic intersection is compared against
// (bench/blob_study.cpp). Marching tetrahedra (core/shapes/marching_tetrahedra.h) over
// F − threshold, with the field's normal −∇F.
#include "core/shapes/blob.h"
#include "core/shapes/mesh.h"
#include "core/shapes/mesh_form.h"

namespace rayo {

// The blob's surface over a grid of cubes of side `cell` covering its bounds.
TriangleMesh tessellate_blob(const Blob& blob, double cell);

// The mesh's distance from the surface, estimated at ten points of each triangle (its corners,
// the points a third along its edges and its centroid) as |F − T| / |∇F|, the first-order
// distance to the level set F = T (Taubin 1991, "Estimation of planar curves, surfaces, and
// nonplanar space curves defined by implicit equations"): the largest, world units.
double blob_mesh_chord(const Blob& blob, const TriangleMesh& mesh);

// Lattice cells across the blob's largest extent at most: the finest mesh of
// bench/blob_study.cpp (2.4 M triangles, 284 MB, some 20 s to build for five elements).
constexpr int kBlobMeshMaxCells = 512;

// The blob's mesh form within `max_chord` (> 0) of the surface, on a lattice of at most
// `max_cells` cells across: the first cell side is the one whose longest tetrahedron edge
// (√3 cells) has a sagitta of max_chord on the smallest lone element's sphere (c²/(8ρ)); then,
// as long as blob_mesh_chord() exceeds the budget, the side shrinks by √(0.9·budget/chord) (the
// error of a linear interpolant falls with the square of the cell), four tries at most. `chord`
// is what the last mesh reached (above max_chord when max_cells stopped it).
MeshForm blob_mesh_form(const Blob& blob, float max_chord, int max_cells = kBlobMeshMaxCells);

}  // namespace rayo
