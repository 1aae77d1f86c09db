#pragma once
// Stanford PLY (turk-1994), rayo's own reader: ASCII, binary_little_endian and
// binary_big_endian. From the element `vertex`: x, y, z (required), nx, ny, nz (kept when all
// three are there) and red, green, blue (kept when all three are there; integer types scaled by
// their largest value, uchar by 255, float and double as they are). From the element `face`: the
// list `vertex_indices` (or `vertex_index`). Every other element and property is read by its
// declared types and dropped, so that what follows it is found where the header says.
//
// Nothing is allocated for what the file does not hold: every element count is checked against
// the bytes after the header (each instance takes at least a byte per binary scalar, two per
// ASCII value) before the vertices are reserved, and every list count against the bytes (binary)
// or values (ASCII) left before its items are read; memory stays a small multiple of the file's
// size. Errors are InputError at `path:line` for the header and ASCII bodies and naming the
// element and instance ("PLY element 'face' instance 7: ...") in both kinds of body.
#include <string>
#include <string_view>

#include "apps/scene/polygon_mesh.h"

namespace rayo {

// The polygons of the PLY file whose bytes are `bytes`, read from `path` (named in errors). Every
// face index is checked against the vertex count, a face of no corners or of more than
// kMaxPolygonVertices is refused, and so is a coordinate beyond the scene's magnitudes
// (core/scene_limits.h) or a colour that is negative or not finite.
PolygonMesh read_ply(std::string_view bytes, const std::string& path);

}  // namespace rayo
