#pragma once
// Triangle meshes from the three simple polygon formats, read by rayo's own readers: Stanford
// PLY (apps/scene/ply_reader.h), STL, ASCII and binary (stl_reader.h), and OFF (off_reader.h).
// They carry geometry only (PLY and OFF variants also per-vertex colours and normals). rayo read
// them through assimp until fuzzing kept finding crashes, heap corruption and multi-gigabyte
// reservations inside it on small malformed files (docs/scene-format.md, "Meshes").
#include <string>
#include <vector>

#include "apps/scene/input_file.h"
#include "apps/scene/mesh_loader.h"
#include "core/shapes/mesh.h"
#include "shading/material.h"

namespace rayo {

// Whether `path` has an extension load_polygon_file reads (.ply, .stl, .off, any case).
bool is_polygon_file(const std::string& path);

// Reads the file through read_input_file (the checks of load_obj) and the reader of its
// extension. Every triangle gets the material named "default" in `materials`
// (default_material_index). Faces of more than three corners are triangulated
// (core/shapes/polygon_triangulation.h), points and lines dropped. PLY vertex colours
// (red/green/blue; integer types scaled to [0, 1] by their largest value, floats as they are)
// and COFF colours go to mesh.colors, like OBJ vertex colours; PLY and NOFF normals are kept
// (unit length); STL facet normals are dropped (flat shading, the triangles joined at shared
// corners, so that "smooth": true can average them) and a file without normals gives an empty
// `normals`. Errors are InputError naming the path: "path:line" for the text formats and PLY
// headers, the element and instance (PLY) or triangle (STL) in binary bodies. A malformed or
// truncated file, counts the file cannot hold (found before anything is allocated), face indices
// out of range, a face of more than kMaxPolygonVertices, coordinates beyond the scene's
// magnitudes, an empty file, a file without triangles.
TriangleMesh load_polygon_file(const std::string& path, std::vector<Material>& materials,
                               const std::string& where, MeshImportStats* stats = nullptr,
                               const FileAccess& access = {});

}  // namespace rayo
