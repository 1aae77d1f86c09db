#pragma once
// `--sphere-method auto`: model no more than the scene needs. Picks, per scene, the cheapest
// sphere representation whose error stays within a budget in pixels, and says why
// (docs/sphere-methods.md has the measurements behind each rule).
#include <string>

#include "apps/scene/scene_description.h"
#include "core/camera.h"

namespace rayo {

struct SphereChoice {
    SphereRepresentation spheres;
    SphereMath math = SphereMath::Stable;
    std::string reason;  // one line for --stats
    // Under auto with spheres: the estimated worst silhouette error of float coordinates over
    // the scene's spheres, in pixels (quoted by `reason` under stable math); 0 when not estimated.
    float worst_float_error_px = 0.0f;
};

// Resolves settings.spheres (when Auto) and settings.sphere_math for this camera. An explicit
// method is kept as it is ("as requested"); under Auto an explicit seed/double math is kept and
// the default stable math may be raised to double where float would miss the budget.
SphereChoice choose_sphere_method(const SceneDescription& description, const Camera& camera);

// The smallest icosphere level whose facets lie at most `max_error_px` inside the true sphere
// for a sphere of projected radius `radius_px` (kIcosphereMaxDepth); kMaxMeshLevel if none is
// enough.
int icosphere_level_for(float radius_px, float max_error_px);

}  // namespace rayo
