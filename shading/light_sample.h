#pragma once
// What a light gives a shading point when sampled (the light interface, docs/architecture.md):
// the unit direction toward the light, the distance to it (infinity for directional lights),
// the radiance arriving along that direction before the cosine, and the pdf of the direction
// (1 for lights that are a single direction: point and directional).
#include <cstdint>
#include <glm/vec2.hpp>
#include <limits>

#include "core/math.h"

namespace rayo {

constexpr uint32_t kNoEmissionImage = std::numeric_limits<uint32_t>::max();

struct LightSample {
    Vec3 direction{0.0f};
    float distance = std::numeric_limits<float>::infinity();
    Vec3 radiance{0.0f};
    float pdf = 1.0f;
    // The point lies on an emitting surface that is also an object of the scene (area lights):
    // its shadow ray must end just short of that very point.
    bool on_surface = false;
    // A point of an emitter whose material has an emission image (MeshEmitter): the radiance is
    // still to be multiplied by that image at `uv` (the integrator holds the images).
    uint32_t emission_material = kNoEmissionImage;
    glm::vec2 uv{0.0f};
};

// A point of a light's own surface that a ray found (the first surface along it): what the light
// needs to say how densely its sampling gives that point (AreaLight::pdf_at).
struct EmitterPoint {
    Vec3 position{0.0f};
    Vec3 normal{0.0f};    // the geometric normal on the emitting side, unit
    Vec3 radiance{0.0f};  // the surface's emitted radiance before any emission image
};

}  // namespace rayo
