#pragma once
// A sphereflake in the manner of the SPD "balls" scene (Haines 1987): a sphere with nine
// children of a third of its radius on its surface, recursively, on a floor, lit by three
// lights. depth d gives Σ 9^i (i = 0..d) spheres (depth 4: 7381). Used by the benchmarks.
#include "apps/scene/scene_description.h"

namespace rayo {

// The spheres alone: a sphere at `center` with its children up to `depth` levels, the first
// nine around `axis` (unit); appended to `spheres`. Also the JSON "sphereflake" object.
constexpr int kMaxSphereflakeDepth = 6;  // 597 871 spheres
void add_sphereflake(std::vector<Sphere>& spheres, const Vec3& center, float radius,
                     const Vec3& axis, int depth, uint32_t material);

SceneDescription make_sphereflake(int depth, int width = 512, int height = 512);

}  // namespace rayo
