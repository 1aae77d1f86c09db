#pragma once
// A sphereflake in the manner of the SPD "balls" scene (Haines 1987): a sphere with nine
// children of a third of its radius on its surface, recursively, on a floor, lit by three
// lights. depth d gives Σ 9^i (i = 0..d) spheres (depth 4: 7381). Used by the benchmarks.
#include "apps/scene/scene_description.h"

namespace rayo {

SceneDescription make_sphereflake(int depth, int width = 512, int height = 512);

}  // namespace rayo
