#pragma once
// What a light gives a shading point when sampled (the light interface, docs/architecture.md):
// the unit direction toward the light, the distance to it (infinity for directional lights),
// the radiance arriving along that direction before the cosine, and the pdf of the direction
// (1 for lights that are a single direction: point and directional).
#include <glm/vec2.hpp>
#include <limits>

#include "core/math.h"

namespace rayo {

struct LightSample {
    Vec3 direction{0.0f};
    float distance = std::numeric_limits<float>::infinity();
    Vec3 radiance{0.0f};
    float pdf = 1.0f;
    // The point lies on an emitting surface that is also an object of the scene (area lights):
    // its shadow ray must end just short of that very point.
    bool on_surface = false;
};

}  // namespace rayo
