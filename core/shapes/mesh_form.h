#pragma once
// A shape's mesh form (issue 11, "model no more than a scene needs"): its parametric pieces
// (core/shapes/tessellation.h) cut finely enough that the surface lies within `max_chord` of the
// triangles, as a TriangleMesh of one material with the analytic normals at the vertices
// (smooth shading, as the icosphere meshes of core/shapes/icosphere.h).
#include <cstdint>
#include <type_traits>

#include "core/shapes/blob.h"
#include "core/shapes/mesh.h"
#include "core/shapes/sphere.h"
#include "core/shapes/tessellation.h"

namespace rayo {

// Cells per direction of a piece at most: 2·1024² triangles per piece bound the mesh of a
// budget the camera is too close for (the choice then reports the chord it reached).
constexpr uint32_t kMeshFormMaxCells = 1024;

struct MeshForm {
    TriangleMesh mesh;
    // Its chord error, world units: the largest of the triangles' bulges
    // (TessellatedMesh::bulge) and the pieces' grid chord errors (grid_chord_error, which sees a
    // rim's polygon); at most about max_chord unless kMeshFormMaxCells stopped the refinement.
    float chord = 0.0f;
};

// max_chord > 0. Pieces that collapse to lines (poles, a disk's centre) leave no triangles there.
MeshForm mesh_form(const SurfacePieces& pieces, float max_chord, uint32_t material);

// Whether a shape takes a method (core/shape_method.h): it has pieces, or it is a blob (its
// mesh form is its marching tetrahedra, core/shapes/blob_mesh.h), and it is not a sphere
// (spheres have their own methods, core/sphere_method.h).
template <typename S>
bool has_mesh_form(const S& shape) {
    if constexpr (std::is_same_v<S, Sphere>) {
        return false;
    } else if constexpr (std::is_same_v<S, Blob>) {
        return true;
    } else {
        SurfacePieces pieces;
        shape.pieces(pieces);
        return !pieces.empty();
    }
}

}  // namespace rayo
