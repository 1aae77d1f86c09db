#pragma once
// A blob (core/shapes/blob.h) tessellated for Embree: the tessellated form that the analytic
// intersection is compared against (bench/blob_study.cpp). Marching tetrahedra
// (core/shapes/marching_tetrahedra.h) over F − threshold, with the field's normal −∇F.
#include "core/shapes/blob.h"
#include "core/shapes/mesh.h"

namespace rayo {

// The blob's surface over a grid of cubes of side `cell` covering its bounds.
TriangleMesh tessellate_blob(const Blob& blob, double cell);

}  // namespace rayo
