#pragma once
// Triangle-mesh import: Wavefront OBJ/MTL (tinyobjloader) and glTF 2.0 .gltf/.glb (tinygltf),
// with the files' materials mapped onto rayo's Phong model (docs/scene-format.md, "Meshes"),
// plus the mesh helpers the scene loaders share (transforms, vertex normals, degenerate faces).
#include <cstddef>
#include <glm/mat4x4.hpp>
#include <string>
#include <vector>

#include "apps/scene/gltf_nodes.h"
#include "apps/scene/input_file.h"
#include "core/shapes/mesh.h"
#include "shading/material.h"

namespace rayo {

// The deepest glTF node hierarchy read (the walk recurses once per level; real assets nest a
// few dozen levels; docs/limits.md).
constexpr size_t kMaxGltfNodeDepth = 1000;
// Most nodes a glTF file may have: at about 1 KB each while tinygltf reads them, 2^19 nodes keep
// the worst file of empty nodes near 0.7 GB (docs/limits.md, "glTF").
constexpr size_t kMaxGltfNodes = size_t(1) << 19;

// What an import did besides building the mesh.
struct MeshImportStats {
    size_t degenerate_triangles = 0;    // zero-area triangles dropped (not an error)
    size_t file_materials = 0;          // materials appended from the file
    std::vector<std::string> warnings;  // "path: what" for input used with a default
};

// Both loaders append the file's materials to `materials` and give every triangle the index
// of its material there. Faces the file assigns no material get the material named "default"
// in `materials` (appended, a default-constructed Material, if there is none). The file's
// normals are kept (unit length; zero where a corner has none, meaning "shade with the
// geometric normal"); a file without normals gives an empty `normals` (flat shading).
// Every file (the mesh, its .mtl libraries, glTF buffers and images) is read through
// read_input_file (apps/scene/input_file.h): regular files of sane size that `access` allows.
// Errors are InputError: a missing or unreadable file names `where` (the caller's place, e.g.
// "scene.json#/objects/2/file") and the resolved path; a malformed OBJ names "path:line" when
// tinyobjloader reports a line; a file without triangles is an error.
TriangleMesh load_obj(const std::string& path, std::vector<Material>& materials,
                      const std::string& where, MeshImportStats* stats = nullptr,
                      const FileAccess& access = {});

// glTF 2.0: POSITION, NORMAL and indices (u8/u16/u32) of the TRIANGLES primitives of every mesh
// instanced by the default scene's nodes (node matrices and TRS applied). .glb and .gltf (base64
// or external buffers). Other primitive modes and sparse accessors are rejected. With `nodes`,
// also the nodes' cameras and lights, and, when nodes->instance_shared_meshes, the meshes that
// several nodes use kept once (apps/scene/gltf_nodes.h; the returned mesh may then be empty).
TriangleMesh load_gltf(const std::string& path, std::vector<Material>& materials,
                       const std::string& where, MeshImportStats* stats = nullptr,
                       const FileAccess& access = {}, GltfNodes* nodes = nullptr);

// The model file extensions import_mesh_file reads (lower case, with the dot), and the same as
// words for messages (".obj, .gltf, .glb, .ply, .stl or .off").
bool is_mesh_file(const std::string& path);
extern const char* const kMeshFileKinds;

struct MeshImportOptions {
    std::string where;  // the caller's place, named in errors (e.g. "s.json#/objects/2/file")
    glm::dmat4 transform{1.0};    // applied to the file's mesh before degenerate faces are dropped
    std::string transform_where;  // named when the transformed mesh leaves the scene's magnitudes
    FileAccess access;
    // glTF only: when given, meshes that several nodes use go here as groups and instances
    // (and the file's cameras and lights), not into the returned mesh; the returned mesh may
    // then be empty when every mesh is shared.
    GltfNodes* gltf_nodes = nullptr;
};

struct ImportedMesh {
    TriangleMesh mesh;
    MeshImportStats stats;  // degenerate_triangles: the loader's and the transform's together
};

// The mesh file at `path` by its extension (load_obj, load_gltf, load_polygon_file), transformed,
// with the degenerate triangles the transform makes dropped too. A dropped triangle is counted and
// reported by a warning in stats.warnings ("where: dropped N degenerate ..."); an unknown
// extension, a mesh left without triangles, or a transformed coordinate beyond the scene's
// magnitudes is an InputError.
ImportedMesh import_mesh_file(const std::string& path, std::vector<Material>& materials,
                              const MeshImportOptions& options);

// Helpers the mesh loaders share (mesh_loader.cpp, polygon_file_loader.cpp).
std::string file_name(const std::string& path);  // the last path component
// A parser's (possibly multi-line) report as one line, trailing blanks trimmed.
std::string one_line(std::string text);
// "path:line" when `message` names a line ("line 12", "line: 12"), else `path`.
std::string place_with_line(const std::string& path, const std::string& message);
// InputError(where, "mesh file 'path' contains no (non-degenerate) triangles") when it has none.
void check_mesh_not_empty(const TriangleMesh& mesh, const std::string& path,
                          const std::string& where);

// Applies an affine transform to positions, (by the inverse transpose) normals and tangents; a
// transform that mirrors (negative determinant) also flips the winding so faces keep their
// orientation, and the tangents' handedness.
void transform_mesh(TriangleMesh& mesh, const glm::dmat4& transform);

// On a mesh with a normal-mapped material (`materials` indexed as its material ids), computes
// the tangents the file does not give (core/shapes/mesh_tangents.h); other meshes are left as
// they are.
void complete_tangents(TriangleMesh& mesh, const std::vector<Material>& materials);

// Replaces the normals by area-weighted averages of the adjacent faces' normals.
void compute_vertex_normals(TriangleMesh& mesh);

// Removes triangles of zero area (or with non-finite vertices); returns how many it removed.
size_t drop_degenerate_triangles(TriangleMesh& mesh);

// Index in `materials` of the material named "default", appending one when there is none.
uint32_t default_material_index(std::vector<Material>& materials);

}  // namespace rayo
