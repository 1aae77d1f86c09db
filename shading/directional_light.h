#pragma once
// A directional light (the sun): parallel rays of one colour and intensity, no attenuation.
#include <limits>

#include "shading/light_sample.h"

namespace rayo {

struct DirectionalLight {
    Vec3 direction{0.0f, -1.0f, 0.0f};  // the direction light travels (unit)
    Vec3 color{1.0f};
    float intensity = 1.0f;

    int sample_count() const { return 1; }
    bool sample(const Vec3& /*point*/, const glm::vec2& /*u*/, LightSample& out) const {
        out.direction = -direction;
        out.distance = std::numeric_limits<float>::infinity();
        out.radiance = color * intensity;
        out.pdf = 1.0f;
        return true;
    }
};

}  // namespace rayo
