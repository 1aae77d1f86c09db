#pragma once
// A TriangleMesh as Embree triangles: Embree-owned vertex and index buffers, back faces culled
// for one-sided meshes (NFF polygons), interpolated vertex normals where all three corners
// have one; cutouts.
#include <memory>

#include "core/cutout.h"
#include "core/geometry_binding.h"
#include "core/shapes/mesh.h"

namespace rayo {

// `mesh_index` goes to SurfaceHit::mesh; `shape_index` to SurfaceHit::shape. With `cutouts`
// the mesh's hits where cutouts->hole says so are no hits, for every ray (Embree intersection
// and occlusion filters on this geometry alone; docs/models.md, "Cutouts").
std::unique_ptr<GeometryBinding> make_mesh_binding(const TriangleMesh& mesh, uint32_t mesh_index,
                                                   uint32_t shape_index,
                                                   const CutoutTest* cutouts = nullptr);

// Whether any triangle of `mesh` has a material `cutouts` cuts.
bool mesh_has_cutout(const TriangleMesh& mesh, const CutoutTest& cutouts);

}  // namespace rayo
