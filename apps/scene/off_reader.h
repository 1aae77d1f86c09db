#pragma once
// OFF, the Object File Format of Geomview (geomview-off), rayo's own reader: the keyword `OFF`
// (the counts may follow it on its line, or in the same word: "OFF8 6 0"), the counts
// `VERTICES FACES [EDGES]`, a line per vertex `x y z`, a line per face `n i1 ... in` (a colour
// after the indices, up to 4 numbers, is allowed and not read). '#' starts a comment; blank
// lines are skipped. The variants with more numbers per vertex are read too: NOFF (a normal,
// kept), COFF (a colour r g b [a], kept: floats in [0, 1], or integers in 0..255 when every
// colour in the file is an integer and one exceeds 1), STOFF (texture coordinates, dropped) and
// their combinations in Geomview's order [ST][C][N]OFF; 4OFF, nOFF and binary OFF are refused by
// name.
#include <string>
#include <string_view>

#include "apps/scene/polygon_mesh.h"

namespace rayo {

// The polygons of the OFF file whose bytes are `bytes`, read from `path`. Errors are InputError
// at `path:line`: the counts are checked against the bytes that follow them before anything is
// allocated, every face index against the vertex count, a face of more than
// kMaxPolygonVertices, a coordinate beyond the scene's magnitudes (core/scene_limits.h), a
// negative colour.
PolygonMesh read_off(std::string_view bytes, const std::string& path);

}  // namespace rayo
