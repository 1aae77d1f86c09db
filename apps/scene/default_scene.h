#pragma once
// The built-in scene `rayo render` shows without a scene file: spheres (diffuse, mirror, glass),
// a triangle mesh, hard shadows from a point and a directional light, on a floor.
#include "apps/scene/scene_description.h"

namespace rayo {

SceneDescription make_default_scene();

}  // namespace rayo
