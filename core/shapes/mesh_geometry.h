#pragma once
// A TriangleMesh as Embree triangles: Embree-owned vertex and index buffers, back faces culled
// for one-sided meshes (NFF polygons), interpolated vertex normals where all three corners
// have one.
#include <memory>

#include "core/geometry_binding.h"
#include "core/shapes/mesh.h"

namespace rayo {

// `mesh_index` goes to SurfaceHit::mesh; `shape_index` to SurfaceHit::shape.
std::unique_ptr<GeometryBinding> make_mesh_binding(const TriangleMesh& mesh, uint32_t mesh_index,
                                                   uint32_t shape_index);

}  // namespace rayo
