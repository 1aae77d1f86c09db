#pragma once
// How an Accel builds its Embree scene: the sphere representation and math of the
// analytic-vs-BVH comparison (core/sphere_method.h) and the triangle watertightness flag.
#include "core/sphere_method.h"

namespace rayo {

struct AccelOptions {
    SphereRepresentation spheres;                 // method; Auto must be resolved before
    SphereMath sphere_math = SphereMath::Stable;  // for the analytic methods (user, bruteforce)
    bool robust = true;  // RTC_SCENE_FLAG_ROBUST: watertight triangles (docs/architecture.md)
};

}  // namespace rayo
