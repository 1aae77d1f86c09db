#pragma once
// The sphere's Embree representations, selectable per render for the analytic-vs-BVH comparison
// (docs/sphere-methods.md): user geometry running rayo's quadratic in the chosen math (the
// default, through the generic callbacks), Embree's built-in point spheres, icosphere meshes,
// and brute force (one user primitive whose callback tests every sphere: no BVH over spheres).
#include <memory>
#include <vector>

#include "core/accel_options.h"
#include "core/geometry_binding.h"
#include "core/shapes/sphere.h"

namespace rayo {

// Overloads the generic make_binding (core/user_geometry.h) for spheres.
std::unique_ptr<GeometryBinding> make_binding(const std::vector<Sphere>& spheres,
                                              uint32_t shape_index, const AccelOptions& options);

}  // namespace rayo
