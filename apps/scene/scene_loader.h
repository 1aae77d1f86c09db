#pragma once
// Loads a scene file by its extension: .json (native format), .nff (Standard Procedural
// Databases), or a model file (.obj, .gltf, .glb, .ply, .stl, .off) framed as
// apps/scene/model_scene.h says. Errors are InputErrors naming the file and place.
#include <string>

#include "apps/scene/model_scene.h"
#include "apps/scene/nff_loader.h"
#include "apps/scene/scene_description.h"

namespace rayo {

// Per-format reading choices; each applies only to files of its format.
struct SceneLoadOptions {
    NffOptions nff;
    // Confine every file the scene references to the scene file's directory tree
    // (`--restrict-paths`; docs/limits.md, "Trust model").
    bool restrict_paths = false;
    ModelFraming model;
};

SceneDescription load_scene_file(const std::string& path, const SceneLoadOptions& options = {});

}  // namespace rayo
