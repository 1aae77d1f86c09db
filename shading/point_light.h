#pragma once
// A point light with colour, intensity and distance attenuation (seed 000: f(d) = 1/(d + d0) or
// 1/(a0 + a1·d + a2·d²); seed 003 eq. 2.8 clamps to 1; the inverse square of glTF's
// KHR_lights_punctual, optionally windowed to a range).
#include <algorithm>
#include <optional>

#include "core/shapes/shape_fields.h"
#include "shading/light_sample.h"
#include "shading/light_text.h"

namespace rayo {

struct Attenuation {
    enum class Kind { None, Linear, Quadratic, InverseSquare };
    Kind kind = Kind::None;
    float d0 = 0.0f;                        // Linear: 1/(d + d0)
    float a0 = 1.0f, a1 = 0.0f, a2 = 0.0f;  // Quadratic: min(1, 1/(a0 + a1·d + a2·d²))
    // InverseSquare: 1/d², times KHR_lights_punctual's recommended window
    // clamp(1 − (d/range)⁴, 0, 1)² when range > 0 (no window when range = 0).
    float range = 0.0f;

    float factor(float distance) const {
        switch (kind) {
            case Kind::Linear:
                return 1.0f / (distance + d0);
            case Kind::Quadratic:
                return std::min(1.0f, 1.0f / (a0 + a1 * distance + a2 * distance * distance));
            case Kind::InverseSquare: {
                float window = 1.0f;
                if (range > 0.0f) {
                    const float r = distance / range, r2 = r * r;
                    window = std::clamp(1.0f - r2 * r2, 0.0f, 1.0f);
                    window *= window;
                }
                return window / (distance * distance);
            }
            case Kind::None:
                break;
        }
        return 1.0f;
    }
};

struct PointLight {
    static constexpr const char* kName = "point";
    Vec3 position{0.0f};
    Vec3 color{1.0f};
    float intensity = 1.0f;
    Attenuation attenuation;

    // The scene-file fields (core/shapes/shape_fields.h; docs/scene-format.md, "lights").
    template <typename F>
    void fields(F& f) {
        f("position", position, FieldKind::Point);
        f.optional("color", color, FieldKind::Colour);
        f.optional("intensity", intensity, FieldKind::NonNegative);
        f.optional("attenuation", attenuation, FieldKind::Attenuation);
    }
    std::optional<FieldProblem> problem() const { return std::nullopt; }
    // " position x y z color r g b intensity i", after kName (shading/light_text.h).
    void describe(std::ostream& out) const {
        out << " position ";
        write_triple(out, position);
        write_color_and_intensity(out, color, intensity);
    }
    // A single point: no direction has a density (sampling integrators treat it as a delta).
    static constexpr bool kDelta = true;
    float pdf(const Vec3& /*point*/, const Vec3& /*direction*/) const { return 0.0f; }

    int sample_count() const { return 1; }
    // False at the light's own position (no direction).
    bool sample(const Vec3& point, const glm::vec2& /*u*/, LightSample& out) const {
        const Vec3 offset = position - point;
        out.distance = glm::length(offset);
        if (!(out.distance > 0.0f)) return false;
        out.direction = offset / out.distance;
        out.radiance = color * intensity * attenuation.factor(out.distance);
        out.pdf = 1.0f;
        return true;
    }
};

}  // namespace rayo
