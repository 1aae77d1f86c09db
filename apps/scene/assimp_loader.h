#pragma once
// Triangle meshes in the formats tinyobjloader and tinygltf do not read, through the Open Asset
// Import Library (assimp, Debian's libassimp-dev): Stanford PLY, STL (ASCII and binary) and
// OFF. These formats carry geometry only (PLY also per-vertex colours and normals); formats that
// carry whole scenes (Collada, FBX, 3DS, ...) are not exposed: their materials, textures,
// cameras and lights would be half translated (docs/scene-format.md, "Meshes").
#include <string>
#include <vector>

#include "apps/scene/input_file.h"
#include "apps/scene/mesh_loader.h"
#include "core/shapes/mesh.h"
#include "shading/material.h"

namespace rayo {

// Whether `path` has an extension load_assimp_mesh reads (.ply, .stl, .off).
bool is_assimp_mesh_file(const std::string& path);

// Reads the file through read_input_file (the checks of load_obj) and assimp. Every triangle
// gets the material named "default" in `materials` (default_material_index). PLY vertex colours
// (red/green/blue, bytes scaled to [0, 1]) go to mesh.colors as they are, like OBJ vertex
// colours; PLY normals are kept (unit length); STL facet normals are dropped (flat shading, the
// triangles joined at shared corners, so that "smooth": true can average them) and a file
// without normals gives an empty `normals`. Errors are InputError naming the path (and
// "path:line" when the message has a line): a malformed or truncated file, face indices out of
// range, a PLY header declaring more elements than the file can hold (found before assimp
// allocates them), coordinates beyond the scene's magnitudes, a file without triangles.
TriangleMesh load_assimp_mesh(const std::string& path, std::vector<Material>& materials,
                              const std::string& where, MeshImportStats* stats = nullptr,
                              const FileAccess& access = {});

}  // namespace rayo
