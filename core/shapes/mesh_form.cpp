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
    // tessellate() refines each direction toward half the budget from a sampled estimate; where
    // the sum still misses it (a paraboloid's steep vertex), the budget is tightened by the miss.
    TessellatedMesh cut;
    float chord = 0.0f;
    for (int attempt = 0; attempt < 4; ++attempt) {
        tessellate(pieces, options, cut);
        chord = 0.0f;
        for (float b : cut.bulge) chord = std::max(chord, b);
        for (size_t p = 0; p < pieces.size(); ++p) {
            chord = std::max(chord, static_cast<float>(grid_chord_error(pieces[p], cut.grids[p])));
        }
        if (chord <= max_chord) break;
        options.max_chord *= 0.95f * max_chord / chord;
    }
    MeshForm form;
    form.chord = chord;
    form.mesh.positions = std::move(cut.positions);
    form.mesh.normals = std::move(cut.normals);
    form.mesh.triangles = std::move(cut.triangles);
    form.mesh.materials.assign(form.mesh.triangles.size(), material);

    return form;
}

}  // namespace rayo
