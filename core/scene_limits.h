#pragma once
// The largest magnitude a scene number may have, with the one test and the one wording every
// loader uses for it (JSON, NFF, OBJ/MTL, glTF, transformed meshes; docs/limits.md "Numbers").
#include <cmath>

namespace rayo {

// Intersections square coordinates and radii (r², |f|², the discriminant), and 1e18² = 1e36
// stays finite in float while 1e20² does not: a larger sphere would silently vanish. The loaders
// refuse anything beyond it (docs/limits.md).
constexpr double kMaxSceneMagnitude = 1e18;

// Whether a scene may contain the number `v`: finite and of magnitude <= kMaxSceneMagnitude.
inline bool within_scene_magnitude(double v) {
    return std::isfinite(v) && std::fabs(v) <= kMaxSceneMagnitude;
}

// Whether every coordinate of the point `p` (a Vec3) is: each tested, since max_abs_component
// (glm::max) drops a NaN in y or z (a PLY vertex (0, NaN, 0) was accepted; found by
// fuzz/mesh_fuzz.cpp).
template <typename Point>
inline bool point_within_scene_magnitude(const Point& p) {
    return within_scene_magnitude(p.x) && within_scene_magnitude(p.y) &&
           within_scene_magnitude(p.z);
}

// The rule in words, for the loaders' "expected <rule>, got <value>" messages.
constexpr const char* kSceneMagnitudeRule =
    "a finite number (in float range) of magnitude <= 1e18, so that its square fits a float";
static_assert(kMaxSceneMagnitude == 1e18, "kSceneMagnitudeRule quotes the limit");

}  // namespace rayo
