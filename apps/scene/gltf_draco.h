#pragma once
// Draco-compressed glTF meshes (KHR_draco_mesh_compression), decoded with Google's Draco library
// (Debian's libdraco-dev) around Debian's tinygltf, which is built without Draco: before
// tinygltf reads the file, the compressed primitives' `indices` are removed from its JSON (the
// indices accessor of a compressed primitive has no bufferView, which tinygltf refuses); after,
// each compressed primitive is decoded once per bufferView and its indices and attributes become
// new accessors on new buffers, so that the rest of load_gltf reads them as any other
// (docs/scene-format.md, "Meshes").
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace tinygltf {
class Model;
}

namespace rayo {

inline constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";

// Removes `indices` from every primitive of `root` (a glTF document) that has the Draco
// extension; returns whether there was one.
bool strip_draco_indices(nlohmann::json& root);

// Decodes every primitive of `model` that has the Draco extension (their `indices` removed by
// strip_draco_indices). Errors are InputError(path, "mesh M primitive P: ...") naming what is
// wrong: a bufferView or accessor out of range, an attribute the Draco data lacks, a component
// count or type that differs from the accessor's, data Draco cannot decode, a point cloud.
void decode_draco_primitives(tinygltf::Model& model, const std::string& path);

}  // namespace rayo
