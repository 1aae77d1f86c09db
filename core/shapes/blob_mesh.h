#pragma once
// A blob (core/shapes/blob.h) tessellated for Embree: the tessellated form that the analytic
// intersection is compared against (bench/blob_study.cpp). Marching tetrahedra — the marching
// cubes family (Lorensen & Cline 1987) with each grid cube split into six tetrahedra around its
// main diagonal (a decomposition neighbouring cubes agree on), which needs no 256-case table and
// has no ambiguous cases: a tetrahedron with one or three corners inside the solid gets one
// triangle, with two a quad (two triangles). Vertices lie on the cube edges where linear
// interpolation of F crosses the threshold, one per edge (shared by the triangles around it),
// with the field's normal −∇F.
#include "core/shapes/blob.h"
#include "core/shapes/mesh.h"

namespace rayo {

// The blob's surface over a grid of cubes of side `cell` covering its bounds.
TriangleMesh tessellate_blob(const Blob& blob, double cell);

}  // namespace rayo
