#include "apps/scene/sphere_method_choice.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/shapes/icosphere.h"

namespace rayo {
namespace {

constexpr float kFloatEpsilon = 1.1920929e-7f;  // 2^-23

}  // namespace

int icosphere_level_for(float radius_px, float max_error_px) {
    for (int level = 0; level <= kMaxMeshLevel; ++level) {
        if (radius_px * kIcosphereMaxDepth[level] <= max_error_px) return level;
    }
    return kMaxMeshLevel;
}

SphereChoice choose_sphere_method(const SceneDescription& d, const Camera& camera) {
    SphereChoice choice;
    choice.spheres = d.settings.spheres;
    choice.math = d.settings.sphere_math;
    if (choice.spheres.method != SphereMethod::Auto) {
        choice.reason = "as requested";
        return choice;
    }
    std::ostringstream reason;
    if (d.scene.shapes.of<Sphere>().empty()) {
        choice.spheres.method = SphereMethod::User;
        const bool grouped =
            std::any_of(d.scene.groups.begin(), d.scene.groups.end(),
                        [](const ShapeGroup& g) { return !g.shapes.of<Sphere>().empty(); });
        // Spheres in instanced groups (core/instance.h) stay analytic: their pixel size depends
        // on every instance's transform, which this estimate does not follow.
        choice.reason =
            grouped ? "analytic (the spheres are in groups, placed by instances)" : "no spheres";
        return choice;
    }
    // Angular size of a pixel (radians) and the scene's largest coordinate magnitude.
    const float pixel_angle = camera.pixel_angle();
    float max_magnitude = max_abs_component(camera.desc().eye);
    float largest_radius_px = 0.0f;
    float worst_float_error_px = 0.0f;
    for (const Sphere& s : d.scene.shapes.of<Sphere>()) {
        const float distance = glm::max(glm::length(s.center - camera.desc().eye), s.radius);
        max_magnitude = glm::max(max_magnitude, max_abs_component(s.center) + s.radius);
        largest_radius_px = glm::max(largest_radius_px, s.radius / distance / pixel_angle);
        // The stable float form loses about one ulp of the coordinates' magnitude on the
        // perpendicular distance (docs/sphere-methods.md): a silhouette shift of ε·M world
        // units, ε·M/(distance·pixel angle) pixels.
        const float magnitude =
            glm::max(max_abs_component(s.center), max_abs_component(camera.desc().eye));
        worst_float_error_px = glm::max(
            worst_float_error_px, 4.0f * kFloatEpsilon * magnitude / (distance * pixel_angle));
    }
    choice.worst_float_error_px = worst_float_error_px;
    const float budget = d.settings.max_error_px;
    // Analytic spheres through Embree user geometry are exact to float precision and, in our
    // measurements, as cheap as any other representation (docs/sphere-methods.md).
    choice.spheres.method = SphereMethod::User;
    if (d.settings.sphere_math != SphereMath::Stable) {
        reason << "user/" << sphere_math_name(choice.math) << ": analytic, with the requested math";
    } else if (worst_float_error_px > budget) {
        // Not double: the study found double wrong exactly as often as float here, because the
        // scene's float coordinates already carry the error (docs/stability.md).
        choice.math = SphereMath::Stable;
        reason << "user/stable: beyond float's resolution: coordinates this large put silhouettes "
               << "up to " << worst_float_error_px << " px off (> budget " << budget
               << " px) for every method, double included; move the scene near the origin";
    } else {
        choice.math = SphereMath::Stable;
        reason << "user/stable: analytic and exact (float error <= " << worst_float_error_px
               << " px <= budget " << budget << " px); a mesh would need level "
               << icosphere_level_for(largest_radius_px, budget) << " for the largest sphere ("
               << largest_radius_px << " px radius)";
    }
    choice.reason = reason.str();
    return choice;
}

}  // namespace rayo
