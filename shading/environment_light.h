#pragma once
// The environment light: radiance arriving from infinitely far away in every direction, uniform
// (`color`) or from an equirectangular image (latitude-longitude, any image OpenImageIO reads;
// HDR expected), times `intensity`, turned by `rotation` degrees about +y. Rays that leave the
// scene see it; it is importance-sampled by the image's brightness (a piecewise-constant 2-D
// distribution over the texels, weighted by the solid angle each covers), uniform over the
// sphere without an image. docs/path-tracing.md, "The environment".
//
// The mapping: a direction d (world, after the rotation) has the polar angle θ = acos(d.y) from
// +y and the azimuth φ = atan2(d.x, −d.z); the texel coordinates are u = 0.5 + φ/2π (the
// image's centre column looks along −z, +x to its right) and v = θ/π (row 0 is the zenith).
#include <memory>
#include <optional>
#include <vector>

#include "core/piecewise_constant.h"
#include "core/shapes/shape_fields.h"
#include "shading/light_sample.h"
#include "shading/light_text.h"

namespace rayo {

// An equirectangular image as linear RGB radiance with its sampling distribution.
class EnvironmentMap {
  public:
    // `texels` row by row, row 0 the zenith; width, height >= 1, every value finite and >= 0.
    EnvironmentMap(int width, int height, std::vector<Vec3> texels);

    int width() const { return m_width; }
    int height() const { return m_height; }
    // The texel at (u, v) ∈ [0,1)² (nearest: the radiance is constant over each texel, as the
    // distribution that samples it).
    Vec3 lookup(float u, float v) const;
    // A point (u, v) for uniform (ux, uy), with its density per unit area of [0,1)².
    void sample(float ux, float uy, float& u, float& v, float& density) const {
        m_distribution.sample(ux, uy, u, v, density);
    }
    float density(float u, float v) const { return m_distribution.density(u, v); }

  private:
    int m_width, m_height;
    std::vector<Vec3> m_texels;
    PiecewiseConstant2D m_distribution;
};

struct EnvironmentLight {
    static constexpr const char* kName = "environment";
    Vec3 color{1.0f};
    float intensity = 1.0f;
    float rotation = 0.0f;  // degrees about +y
    int samples = 16;       // points per shading point (Whitted, ambient occlusion)
    std::shared_ptr<const EnvironmentMap> map;  // null: uniform `color`

    // The scene file's fields besides "image" (read by the scene reader, which loads the map).
    template <typename F>
    void fields(F& f) {
        f.optional("color", color, FieldKind::Colour);
        f.optional("intensity", intensity, FieldKind::NonNegative);
        f.optional("rotation", rotation, FieldKind::Number);
        f.optional("samples", samples, FieldKind::Integer);
    }
    std::optional<FieldProblem> problem() const {
        if (samples < 1 || samples > 4096) {
            return FieldProblem{"samples", "expected an integer in [1, 4096]"};
        }
        return std::nullopt;
    }

    // "[ image WxH] color ... intensity ... rotation R samples S".
    void describe(std::ostream& out) const {
        if (map) out << " image " << map->width() << "x" << map->height();
        write_color_and_intensity(out, color, intensity);
        out << " rotation " << rotation << " samples " << samples;
    }

    // The radiance a ray leaving the scene along `direction` (unit) sees.
    Vec3 radiance(const Vec3& direction) const;

    static constexpr bool kDelta = false;
    int sample_count() const { return samples; }
    // A direction for u ∈ [0,1)², distance infinity: by the map's distribution, or uniform.
    bool sample(const Vec3& point, const glm::vec2& u, LightSample& out) const;
    // The solid-angle density of sample's `direction`.
    float pdf(const Vec3& point, const Vec3& direction) const;
    float pdf_at(const Vec3& point, const Vec3& direction, const EmitterPoint&) const {
        return pdf(point, direction);
    }
    // What a ray along `direction` that reaches the light sees: radiance(direction), from
    // infinitely far, so no point of arrival (a ray leaving the scene passes EmitterPoint{}).
    Vec3 emitted(const Vec3& direction, const EmitterPoint&) const { return radiance(direction); }

  private:
    // The direction in the image's frame (the rotation undone), and back.
    Vec3 to_image(const Vec3& direction) const;
    Vec3 from_image(const Vec3& direction) const;
};

}  // namespace rayo
