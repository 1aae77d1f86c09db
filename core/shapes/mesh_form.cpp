#include "core/shapes/mesh_form.h"

#include <algorithm>

namespace rayo {

MeshForm mesh_form(const SurfacePieces& pieces, float max_chord, uint32_t material) {
    TessellationOptions options;
    options.max_chord = max_chord;
    // As coarse as the budget allows: a triangle's worth of cells around, one along; the chord
    // refinement (tessellate()) does the rest.
    options.min_around = 3;
    options.min_along = 2;
    options.max_cells = kMeshFormMaxCells;
    TessellatedMesh cut;
    tessellate(pieces, options, cut);
    MeshForm form;
    form.mesh.positions = std::move(cut.positions);
    form.mesh.normals = std::move(cut.normals);
    form.mesh.triangles = std::move(cut.triangles);
    form.mesh.materials.assign(form.mesh.triangles.size(), material);
    for (float b : cut.bulge) form.chord = std::max(form.chord, b);
    return form;
}

}  // namespace rayo
