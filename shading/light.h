#pragma once
// The lights the integrator samples. Every light type provides
//   bool sample(const Vec3& point, const glm::vec2& u, LightSample& out) const;
//   int sample_count() const;  // points per shading point: 1, or an area light's `samples`
// (shading/light_sample.h; u in [0,1)² picks a point on lights with an extent). Adding a light
// type is its file pair and its entry in the list below; the integrator only calls
// sample_light, light_sample_count and light_sample_u (docs/architecture.md, "Extension points").
#include <cstdint>
#include <cstring>
#include <utility>
#include <variant>

#include "core/sampling.h"
#include "shading/area_light.h"
#include "shading/directional_light.h"
#include "shading/point_light.h"
#include "shading/spot_light.h"

namespace rayo {

using Light = std::variant<PointLight, DirectionalLight, AreaLight, SpotLight>;

template <typename F, size_t... I>
void for_each_light(F&& f, std::index_sequence<I...>) {
    (f(std::variant_alternative_t<I, Light>{}), ...);
}
// Calls f(L{}) for each registered light type L, in order (the JSON reader's dispatch by
// L::kName).
template <typename F>
void for_each_light(F&& f) {
    for_each_light(f, std::make_index_sequence<std::variant_size_v<Light>>{});
}

// The solid-angle density of `direction` at `point` under sample_light with uniform u: what a
// sampling integrator weighs a direction found by its scattering function with (multiple
// importance sampling); 0 for the delta lights (point, spot, directional).
inline float light_pdf(const Light& light, const Vec3& point, const Vec3& direction) {
    return std::visit([&](const auto& l) { return l.pdf(point, direction); }, light);
}
inline bool light_is_delta(const Light& light) {
    return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::kDelta; }, light);
}

inline bool sample_light(const Light& light, const Vec3& point, const glm::vec2& u,
                         LightSample& out) {
    return std::visit([&](const auto& l) { return l.sample(point, u, out); }, light);
}

inline int light_sample_count(const Light& light) {
    return std::visit([](const auto& l) { return l.sample_count(); }, light);
}

// Sample `s` of `count` of light `light_index` at the shading point `point`: one jittered point
// per cell of a stratified grid over [0,1)² (core/sampling.h stratified_offset), from the
// stateless hash of the point's coordinates, so that the image is the same for any thread count
// and tile order. One sample is the centre (0.5, 0.5).
inline glm::vec2 light_sample_u(const Vec3& point, uint32_t light_index, uint32_t s,
                                uint32_t count) {
    uint32_t bits[3];
    std::memcpy(&bits[0], &point.x, sizeof(float));
    std::memcpy(&bits[1], &point.y, sizeof(float));
    std::memcpy(&bits[2], &point.z, sizeof(float));
    const uint32_t key = hash_combine(hash_combine(hash_u32(bits[0]), bits[1]), bits[2]);
    const PixelOffset o = stratified_offset(key, light_index, s, count);
    return glm::vec2(o.dx + 0.5f, o.dy + 0.5f);
}

}  // namespace rayo
