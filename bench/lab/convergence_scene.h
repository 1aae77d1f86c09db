#pragma once
// The scene `rayo bench convergence` studies when given none: the Cornell box of
// scenes/cornell_box.json, whose text CMake builds into the lab library
// (bench/lab/convergence_scene.cpp.in), so the command needs no source tree beside it.
#include "apps/scene/scene_description.h"

namespace rayo {

// The name the built-in box goes by in the study's files and errors.
inline constexpr const char* kConvergenceBuiltInScene = "scenes/cornell_box.json (built in)";

SceneDescription convergence_cornell_box();

}  // namespace rayo
