#pragma once
// Light through a medium (seed 004: extinction decays exponentially with distance at constant
// absorption; fog blends toward the scattered colour with distance): the scene's fog, which every
// ray outside the objects travels through, and Beer–Lambert absorption inside dielectrics.
#include <cmath>

#include "core/math.h"

namespace rayo {

// Beer–Lambert transmittance exp(−σ·d) per channel over a path of length d (σ per unit length).
inline Vec3 beer_lambert(const Vec3& sigma, float distance) {
    return Vec3(std::exp(-sigma.x * distance), std::exp(-sigma.y * distance),
                std::exp(-sigma.z * distance));
}

// Uniform fog (seed 004): radiance L seen through a distance d of fog arrives as
//   L·e^(−σd) + C·(1 − e^(−σd)),
// C the fog colour and σ its density; a ray that hits nothing (d = ∞) sees C. Density 0 = no fog.
struct Fog {
    Vec3 color{0.0f};
    float density = 0.0f;

    bool enabled() const { return density > 0.0f; }
    Vec3 apply(const Vec3& radiance, float distance) const {
        if (!std::isfinite(distance)) return color;
        const float transmittance = std::exp(-density * distance);
        return radiance * transmittance + color * (1.0f - transmittance);
    }
};

}  // namespace rayo
