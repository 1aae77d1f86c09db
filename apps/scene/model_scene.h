#pragma once
// A model file rendered with no scene file around it (`rayo render model.obj`): the mesh and its
// materials as the file gives them, framed by a camera on the model's bounding sphere, lit by a
// key and a fill light, standing on a ground square (docs/scene-format.md, "Model files").
#include <optional>
#include <string>

#include "apps/scene/input_file.h"
#include "apps/scene/scene_description.h"

namespace rayo {

// The framing choices a user can override (`--view-dir`, `--no-ground`, `--camera`,
// `--auto-lights`, `--no-instances`).
struct ModelFraming {
    // From the model's centre toward the eye; default a three-quarter view from the front
    // (+z), right (+x) and above (+y, the up axis of glTF and of most OBJ files). Setting it
    // without `camera` chooses the automatic framing over the file's cameras.
    std::optional<Vec3> view_direction;
    bool ground = true;
    // A camera of the file by name (the camera's or its node's) or by index in `rayo info`'s
    // list, or "auto" for the automatic framing. Unset: the file's first camera, if any.
    std::optional<std::string> camera;
    // Add the automatic key and fill lights even when the file has lights or emitters.
    bool auto_lights = false;
    // An environment light will light the model (--environment): no automatic lights unless
    // auto_lights.
    bool environment_lit = false;
    // glTF meshes that several nodes use are kept once and placed as instances.
    bool instances = true;
};

// Whether `path` names a model file (is_mesh_file: .obj, .gltf, .glb, .ply, .stl, .off).
bool is_model_file(const std::string& path);

// Loads the model at `path` (load_obj / load_gltf; their errors name `path`) into a scene: the
// file's camera (glTF) or the automatic framing, the file's KHR_lights_punctual lights, its
// emissive triangles as one area light (apps/scene/area_light_emitters.h), the key and fill
// lights when the file has neither, and glTF meshes reused by several nodes as instances. An
// unknown `framing.camera` is an InputError listing the file's cameras.
SceneDescription load_model_scene(const std::string& path, const ModelFraming& framing = {},
                                  const FileAccess& access = {});

}  // namespace rayo
