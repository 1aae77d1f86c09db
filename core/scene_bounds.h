#pragma once
// The axis-aligned box of everything a scene places: the objects placed directly and, through
// every instance's transform, its group's objects. `rayo info` prints it and the framing of
// model files (apps/scene/model_scene.h) centres the camera on it, so both see the same box.
#include <optional>

#include "core/scene.h"

namespace rayo {

// Meshes contribute their vertices (transformed exactly for instances), analytic shapes, height
// fields and voxel grids their bounds() (an instance's: the box around its 8 transformed
// corners). Empty when the scene places nothing.
std::optional<Bounds3> scene_bounds(const Scene& scene);

}  // namespace rayo
