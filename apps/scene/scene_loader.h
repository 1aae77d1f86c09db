#pragma once
// Loads a scene file by its extension: .json (native format) or .nff (Standard Procedural
// Databases). Errors are InputErrors naming the file and place.
#include <string>

#include "apps/scene/scene_description.h"

namespace rayo {

SceneDescription load_scene_file(const std::string& path);

}  // namespace rayo
