#pragma once
// The lights the integrator samples. Every light type provides
//   static constexpr const char* kName;  // its scene-file "type"
//   template <typename F> void fields(F&);  // its scene-file fields (core/shapes/shape_fields.h),
//   std::optional<FieldProblem> problem() const;  // and what they cannot say alone
//   bool sample(const Vec3& point, const glm::vec2& u, LightSample& out) const;
//   float pdf(const Vec3& point, const Vec3& direction) const;  // 0 for the delta lights
//   static constexpr bool kDelta;  // a point or a direction: no ray hits it
//   int sample_count() const;  // points per shading point: 1, or an area light's `samples`
//   void describe(std::ostream&) const;  // what follows kName in `rayo info` (light_text.h)
// and, unless kDelta, what a ray that reaches it needs (multiple importance sampling):
//   float pdf_at(const Vec3& point, const Vec3& direction, const EmitterPoint& at) const;
//   Vec3 emitted(const Vec3& direction, const EmitterPoint& at) const;
// optionally `form(f)`, a choice read before fields() that decides them (an area light's shape),
// and `finish()`, called once the fields are read (a spot's cosines from its angles).
// (shading/light_sample.h; u in [0,1)² picks a point on lights with an extent). Adding a light
// type is its file pair and its entry in the list below; the integrators call the helpers below
// (sample_light, light_pdf, light_pdf_at, light_emitted, light_sample_count, light_sample_u),
// never a light type (docs/architecture.md, "Adding a light").
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>
#include <variant>

#include "core/ray.h"
#include "core/sampling.h"
#include "shading/area_light.h"
#include "shading/directional_light.h"
#include "shading/environment_light.h"
#include "shading/image_texture.h"
#include "shading/point_light.h"
#include "shading/spot_light.h"

namespace rayo {

using Light = std::variant<PointLight, DirectionalLight, AreaLight, SpotLight, EnvironmentLight>;

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
// light_pdf for a direction whose first hit `at` is on the light's own surface (the hit's
// material names the light: SurfaceCoefficients::emitter_light).
inline float light_pdf_at(const Light& light, const Vec3& point, const Vec3& direction,
                          const EmitterPoint& at) {
    return std::visit(
        [&](const auto& l) {
            if constexpr (std::decay_t<decltype(l)>::kDelta) {
                return 0.0f;
            } else {
                return l.pdf_at(point, direction, at);
            }
        },
        light);
}
// The radiance a ray along `direction` (unit) carries back from the light it reaches at `at`, a
// point of the light's surface (SurfaceCoefficients::emitter_light names the light of a hit's
// material); a ray that leaves the scene reaches the environment, infinitely far, and passes
// EmitterPoint{}. None for the delta lights, which no ray reaches.
inline Vec3 light_emitted(const Light& light, const Vec3& direction, const EmitterPoint& at) {
    return std::visit(
        [&](const auto& l) {
            if constexpr (std::decay_t<decltype(l)>::kDelta) {
                return Vec3(0.0f);
            } else {
                return l.emitted(direction, at);
            }
        },
        light);
}
inline bool light_is_delta(const Light& light) {
    return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::kDelta; }, light);
}

// Whether the radiosity solve shoots the light (an area light's surface is a patch), so that
// its light on patch-covered surfaces is in the solution already (apps/scene/area_light_emitters.h
// puts only area lights' surfaces in the scene).
template <typename L>
constexpr bool kLightInRadiositySolve = std::is_same_v<L, AreaLight>;
inline bool light_in_radiosity_solve(const Light& light) {
    return std::visit(
        [](const auto& l) { return kLightInRadiositySolve<std::decay_t<decltype(l)>>; }, light);
}

// The units of LightSample::radiance. A light with an extent (area lights, emissive meshes)
// gives the radiance L of its surface, so its samples average to the irradiance E = ∫ L cos dω.
// A point or a direction (point, spot, directional lights) has no radiance: it gives seed 000's
// intensity Il (eq. [18]: kd·Il·(N·L)), what a white Lambertian surface facing it reflects, which
// is the irradiance E = π·Il (docs/path-tracing.md, "Units").
// Seed 000's local model (Whitted, ambient occlusion) shades with Il: an extended light's E is
// scaled by 1/π, so a Lambertian surface shows kd·E/π as the radiosity solve gives it.
template <typename L>
constexpr float kLightLocalModelScale = L::kDelta ? 1.0f : 1.0f / kPi;
inline float light_local_model_scale(const Light& light) {
    return std::visit(
        [](const auto& l) { return kLightLocalModelScale<std::decay_t<decltype(l)>>; }, light);
}
// A physically based integrator (path) weighs the incident radiance with the scattering function
// f (a Lambertian surface: kd/π): a point's or a direction's Il becomes the irradiance π·Il, so
// both kinds of integrator agree on the direct light of a Lambertian surface.
inline float light_radiometric_scale(const Light& light) {
    return light_is_delta(light) ? kPi : 1.0f;
}

inline bool sample_light(const Light& light, const Vec3& point, const glm::vec2& u,
                         LightSample& out) {
    return std::visit([&](const auto& l) { return l.sample(point, u, out); }, light);
}

// The sample's radiance with the emitter's image applied at the sampled point (emissiveTexture ×
// emissiveFactor, MTL map_Ke × Ke: the radiance a camera ray sees there), before the pdf.
inline Vec3 light_sample_radiance(const LightSample& sample, const ImageTextures* images) {
    if (sample.emission_material == kNoEmissionImage || !images) return sample.radiance;
    return sample.radiance * Vec3(images->lookup(sample.emission_material,
                                                 ImageTextures::Slot::Emission, sample.uv, 0.0f));
}

// The shadow ray of a light sample taken at `point`, from `origin` (the point offset off its
// surface): to just short of the light's point, so that the light's own surface does not block
// it, or unbounded toward a light infinitely far.
inline Ray light_shadow_ray(const Vec3& point, const Vec3& origin, const LightSample& sample) {
    Ray shadow;
    shadow.origin = origin;
    shadow.direction = sample.direction;
    shadow.tnear = 0.0f;
    if (sample.on_surface || std::isfinite(sample.distance)) {
        const Vec3 offset = point + sample.distance * sample.direction - origin;
        const float length = glm::length(offset);
        shadow.direction = offset / length;
        shadow.tfar = length * (1.0f - 1e-5f);
    } else {
        shadow.tfar = std::numeric_limits<float>::infinity();
    }
    return shadow;
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
