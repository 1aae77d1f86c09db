#pragma once
// A directional light (the sun): parallel rays of one colour and intensity, no attenuation.
#include <limits>
#include <optional>

#include "core/shapes/shape_fields.h"
#include "shading/light_sample.h"
#include "shading/light_text.h"

namespace rayo {

struct DirectionalLight {
    static constexpr const char* kName = "directional";
    Vec3 direction{0.0f, -1.0f, 0.0f};  // the direction light travels (unit)
    Vec3 color{1.0f};
    float intensity = 1.0f;

    template <typename F>
    void fields(F& f) {
        f("direction", direction, FieldKind::Direction);
        f.optional("color", color, FieldKind::Colour);
        f.optional("intensity", intensity, FieldKind::NonNegative);
    }
    std::optional<FieldProblem> problem() const { return std::nullopt; }
    void describe(std::ostream& out) const {
        out << " direction ";
        write_triple(out, direction);
        write_color_and_intensity(out, color, intensity);
    }
    static constexpr bool kDelta = true;  // one direction
    float pdf(const Vec3& /*point*/, const Vec3& /*direction*/) const { return 0.0f; }

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
