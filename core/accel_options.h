#pragma once
// How an Accel builds its Embree scene: the sphere representation and math of the
// analytic-vs-BVH comparison (core/sphere_method.h), the triangle watertightness flag and
// which surfaces have holes (core/cutout.h).
#include "core/cutout.h"
#include "core/sphere_method.h"

namespace rayo {

struct AccelOptions {
    SphereRepresentation spheres;                 // method; Auto must be resolved before
    SphereMath sphere_math = SphereMath::Stable;  // for the analytic methods (user, bruteforce)
    bool robust = true;  // RTC_SCENE_FLAG_ROBUST: watertight triangles (docs/architecture.md)
    // Holes in surfaces (core/cutout.h); null: no surface has any (no filter is registered).
    const CutoutTest* cutouts = nullptr;
};

}  // namespace rayo
