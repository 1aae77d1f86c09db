#pragma once
// A model file rendered with no scene file around it (`rayo render model.obj`): the mesh and its
// materials as the file gives them, framed by a camera on the model's bounding sphere, lit by a
// key and a fill light, standing on a ground square (docs/scene-format.md, "Model files").
#include <optional>
#include <string>

#include "apps/scene/input_file.h"
#include "apps/scene/scene_description.h"

namespace rayo {

// The framing choices a user can override (`--view-dir`, `--no-ground`).
struct ModelFraming {
    // From the model's centre toward the eye; default a three-quarter view from the front
    // (+z), right (+x) and above (+y, the up axis of glTF and of most OBJ files).
    std::optional<Vec3> view_direction;
    bool ground = true;
};

// Whether `path` names a model file (is_mesh_file: .obj, .gltf, .glb, .ply, .stl, .off).
bool is_model_file(const std::string& path);

// Loads the model at `path` (load_obj / load_gltf; their errors name `path`) into a scene.
SceneDescription load_model_scene(const std::string& path, const ModelFraming& framing = {},
                                  const FileAccess& access = {});

}  // namespace rayo
