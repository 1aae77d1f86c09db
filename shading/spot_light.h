#pragma once
// A spot light: a point light whose light is confined to a cone about `direction`, with the
// smooth edge of glTF's KHR_lights_punctual: the angular factor is
// clamp((cos θ − cos θouter)/(cos θinner − cos θouter), 0, 1)², θ the angle between the
// direction and the way to the shaded point (full light inside θinner, none outside θouter).
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "shading/point_light.h"

namespace rayo {

struct SpotLight {
    static constexpr const char* kName = "spot";
    Vec3 position{0.0f};
    Vec3 direction{0.0f, -1.0f, 0.0f};  // the cone's axis, the way the light shines (unit)
    Vec3 color{1.0f};
    float intensity = 1.0f;
    Attenuation attenuation;
    float cos_inner = 1.0f;                  // cos θinner (θinner = 0: no full-light core)
    float cos_outer = 0.70710678118654752f;  // cos θouter (glTF's default θouter = π/4)
    // The scene file's cone angles in degrees (glTF's, which are radians, set the cosines
    // directly): 0 <= inner < outer <= 90; finish() derives the cosines.
    float inner_cone_angle = 0.0f, outer_cone_angle = 45.0f;

    template <typename F>
    void fields(F& f) {
        f("position", position, FieldKind::Point);
        f("direction", direction, FieldKind::Direction);
        f.optional("color", color, FieldKind::Colour);
        f.optional("intensity", intensity, FieldKind::NonNegative);
        f.optional("attenuation", attenuation, FieldKind::Attenuation);
        f.optional("inner_cone_angle", inner_cone_angle, FieldKind::NonNegative);
        f.optional("outer_cone_angle", outer_cone_angle, FieldKind::Positive);
    }
    static std::string degrees(float angle) {
        std::ostringstream text;
        text << angle;
        return text.str();
    }
    std::optional<FieldProblem> problem() const {
        if (!(outer_cone_angle <= 90.0f)) {
            return FieldProblem{
                "outer_cone_angle",
                "expected an angle in degrees in (0, 90], got " + degrees(outer_cone_angle)};
        }
        if (!(inner_cone_angle < outer_cone_angle)) {
            return FieldProblem{"inner_cone_angle",
                                "expected an angle in degrees below outer_cone_angle (" +
                                    degrees(outer_cone_angle) + "), got " +
                                    degrees(inner_cone_angle)};
        }
        return std::nullopt;
    }
    // " position ... direction ... cone 0-45 degrees color ... intensity ...".
    void describe(std::ostream& out) const {
        out << " position ";
        write_triple(out, position);
        out << " direction ";
        write_triple(out, direction);
        out << " cone " << glm::degrees(std::acos(cos_inner)) << "-"
            << glm::degrees(std::acos(cos_outer)) << " degrees";
        write_color_and_intensity(out, color, intensity);
    }
    void finish() {
        constexpr float kDegree = 3.14159265358979323846f / 180.0f;
        cos_inner = std::cos(inner_cone_angle * kDegree);
        cos_outer = std::cos(outer_cone_angle * kDegree);
    }
    static constexpr bool kDelta = true;  // a point
    float pdf(const Vec3& /*point*/, const Vec3& /*direction*/) const { return 0.0f; }

    int sample_count() const { return 1; }
    float angular_factor(const Vec3& to_point) const {
        // glTF's scale 1/max(0.001, cos θinner − cos θouter) keeps the edge finite when the two
        // angles meet.
        const float scale = 1.0f / std::max(0.001f, cos_inner - cos_outer);
        const float f = std::clamp((glm::dot(direction, to_point) - cos_outer) * scale, 0.0f, 1.0f);
        return f * f;
    }
    // False at the light's own position and outside the cone.
    bool sample(const Vec3& point, const glm::vec2& /*u*/, LightSample& out) const {
        const Vec3 offset = position - point;
        out.distance = glm::length(offset);
        if (!(out.distance > 0.0f)) return false;
        out.direction = offset / out.distance;
        const float cone = angular_factor(-out.direction);
        if (!(cone > 0.0f)) return false;
        out.radiance = color * intensity * cone * attenuation.factor(out.distance);
        out.pdf = 1.0f;
        return true;
    }
};

}  // namespace rayo
