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

// rayo traces in float, and a spawned ray leaves its surface by 1e-5 of the hit's largest
// coordinate (shading/surface_interaction.cpp, offset_ray_origin): an object smaller than
// kMinSizeToDistance of its distance from the world origin shades with positions quantised to
// a visible fraction of its size and with offsets that reach past it (docs/limits.md, "Scale":
// a unit sphere renders right at 1e5 from the origin, with acne at 1e6).
constexpr float kMinSizeToDistance = 1e-4f;

// The objects placed directly (analytic shapes, meshes, height fields, voxel grids) whose
// bounds' largest side is below kMinSizeToDistance of their largest coordinate.
size_t objects_below_float_resolution(const Scene& scene);

// Embree's triangle test (Plücker, relative to the ray's origin) multiplies a vertex's distance
// from the ray's origin by an edge squared before it divides: a box of ±3e12 seen from 1.2e13
// overflowed a float, its rays came back NaN and Embree aborted ("all(valid, ray.valid())");
// at ±1e12 seen from 4e12 it renders as at unit scale. The render refuses a scene whose
// triangles, at most L from the origin, and eye, E from it, give (L + E)·(2L)² beyond
// kMaxTriangleProduct (docs/limits.md, "Scale"); analytic shapes keep kMaxSceneMagnitude.
constexpr double kMaxTriangleProduct = 1e38;

// The largest coordinate of a triangle the accel will trace (meshes placed directly and through
// instances, and the spheres when `spheres_as_triangles`); 0 when there is none.
float largest_triangle_coordinate(const Scene& scene, bool spheres_as_triangles);

}  // namespace rayo
