#pragma once
// The radiosity solution as the renderer sees it (seed 004: vertex colours by averaging the
// patches around each vertex): the scene's triangle meshes cut into patches and its analytic
// shapes tessellated into them (for the solve only: the renderer still intersects the shapes),
// and after the solve a radiance per patch vertex, interpolated across each patch.
// docs/radiosity.md.
#include <cstdint>
#include <vector>

#include "core/scene.h"
#include "core/shapes/tessellation.h"
#include "core/surface_hit.h"
#include "shading/material.h"
#include "shading/radiosity.h"

namespace rayo {

class RadiosityField {
  public:
    // Cuts every triangle of every mesh into k×k congruent triangles (k the least with edges no
    // longer than patch_size; 1 when patch_size is 0), with the emission and reflectance (kd) of
    // its material; every analytic shape is tessellated (core/shapes/tessellation.h) with cells
    // no longer than patch_size (0: 16 cells around, 8 along a sphere's meridians), one patch
    // per triangle. General quadrics have no tessellation: they are not in the solve.
    // A surface of a two-sided material (Material::double_sided) has a patch per side (but a
    // one-sided mesh, TriangleMesh::one_sided, whose back rays pass through, has none): the
    // front patches of every surface come first, in the order above, then the back patches
    // (the front ones reversed, facing the other way) in the same order, so a scene whose
    // back sides receive nothing solves its front patches to the same bits as with one side.
    RadiosityField(const Scene& scene, const std::vector<Material>& materials, float patch_size);

    const std::vector<RadiosityPatch>& patches() const { return m_patches; }
    // How many of patches() are the back sides of two-sided surfaces (the last ones).
    size_t back_patch_count() const { return m_back_patches; }

    // Stores the solution: each vertex gets the average over the patches around it (those of
    // the same orientation, so a room's corner does not mix its walls, nor a surface its two
    // sides) of B − E, the radiance the patches reflect (their emission the renderer adds).
    void set_solution(const std::vector<DVec3>& radiosity);
    // Flat patches instead of interpolated vertices (the `--gi-view patches` debug view).
    void set_flat(bool flat) { m_flat = flat; }

    // The reflected radiance at a triangle hit or an analytic shape's hit on the side `front`
    // (the side its geometric normal points to) or the back (interpolated from the vertices of
    // the patch that holds it: for an analytic shape, the tessellation's triangle over the same
    // (s, t) of its surface); false for shapes that have no patches, for the back of a
    // one-sided surface and before set_solution.
    bool reflected(const SurfaceHit& hit, bool front, Vec3& radiance) const;

  private:
    static constexpr uint32_t kNoSide = 0xFFFFFFFFu;
    // Where one side's patches and vertices start: patch n of the cut is patch + n, its grid
    // point v the shared vertex m_vertex_of[vertex + v]. kNoSide: the side has no patches.
    struct Side {
        uint32_t patch = kNoSide;
        uint32_t vertex = 0;
    };
    // An analytic shape's tessellation and its sides' patches (one per triangle).
    struct ShapeCut {
        SurfacePieces pieces;
        TessellatedMesh mesh;
        Side sides[2];  // front, back
    };
    bool shape_reflected(const SurfaceHit& hit, bool front, Vec3& radiance) const;

    struct TriangleCut {
        uint32_t k = 1;  // subdivisions per edge
        // Each side: k² patches and (k+1)(k+2)/2 entries of m_vertex_of from there.
        Side sides[2];  // front, back
    };
    const Scene& m_scene;
    std::vector<std::vector<TriangleCut>> m_cuts;     // per mesh, per triangle
    std::vector<std::vector<ShapeCut>> m_shape_cuts;  // per shape type, per shape
    std::vector<RadiosityPatch> m_patches;
    size_t m_back_patches = 0;
    std::vector<uint32_t> m_vertex_of;  // grid point -> shared vertex
    uint32_t m_vertex_count = 0;
    std::vector<Vec3> m_vertex_radiance;
    std::vector<Vec3> m_patch_radiance;
    bool m_flat = false;
};

}  // namespace rayo
