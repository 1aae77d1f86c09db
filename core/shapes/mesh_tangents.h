#pragma once
// Per-vertex tangents of a textured mesh for normal maps (docs/models.md, "Normal maps"):
// Lengyel's method, "Computing Tangent Space Basis Vectors for an Arbitrary Mesh" (2001).
#include "core/shapes/mesh.h"

namespace rayo {

// Fills TriangleMesh::tangents where a vertex has none (w = 0; all of them when the vector is
// empty) from the positions and texture coordinates: each triangle adds its ∂p/∂u and ∂p/∂v
// (solved from its edges and their texture-coordinate differences) to its three corners; a
// vertex's tangent is its ∂p/∂u sum Gram-Schmidt orthogonalised against its normal (the vertex
// normal, else the sum of its triangles' area-weighted normals), w = ±1 whether
// normal × tangent points up the image (decreasing t, TriangleMesh::tangents) or down. A mesh
// without texture coordinates is left as it is; a vertex whose triangles all have collinear
// texture coordinates keeps w = 0. Returns the number of vertices given a tangent.
size_t compute_tangents(TriangleMesh& mesh);

}  // namespace rayo
