#pragma once
// STL (stl-1989), rayo's own reader, ASCII and binary. A binary file is an 80-byte header, a
// 32-bit little-endian triangle count and 50 bytes per triangle (a normal, three corners as
// floats, a 16-bit attribute); an ASCII file is `solid NAME`, facets of `facet normal NX NY NZ`,
// `outer loop`, three `vertex X Y Z`, `endloop`, `endfacet`, then `endsolid`, and may hold several
// solids. A file that begins with `solid` is ASCII unless its size is exactly the binary size its
// count gives (binary headers may begin with "solid" too).
//
// The facet normals are dropped and the corners the facets share are joined (STL repeats every
// corner in each facet that uses it), so that the mesh is shaded flat and `"smooth": true` can
// average the normals around each corner.
#include <string>
#include <string_view>

#include "apps/scene/polygon_mesh.h"

namespace rayo {

// The triangles of the STL file whose bytes are `bytes`, read from `path` (named in errors):
// `path:line` for ASCII, the triangle's number for binary. A binary count the file's size cannot
// hold is refused before anything is allocated; so is a coordinate beyond the scene's magnitudes
// (core/scene_limits.h) and a facet of other than three vertices.
PolygonMesh read_stl(std::string_view bytes, const std::string& path);

}  // namespace rayo
