#pragma once
// The lights the integrator samples. Every light type provides
//   bool sample(const Vec3& point, const glm::vec2& u, LightSample& out) const;
// (shading/light_sample.h; u in [0,1)² picks a point on lights with an extent). Adding a light
// type is its file pair and its entry in the list below; the integrator only calls
// sample_light (docs/architecture.md, "Extension points").
#include <variant>

#include "shading/directional_light.h"
#include "shading/point_light.h"

namespace rayo {

using Light = std::variant<PointLight, DirectionalLight>;

inline bool sample_light(const Light& light, const Vec3& point, const glm::vec2& u,
                         LightSample& out) {
    return std::visit([&](const auto& l) { return l.sample(point, u, out); }, light);
}

}  // namespace rayo
