#include "shading/texture.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.h"
#include "core/tsan_handoff.h"

namespace rayo {
namespace {

// Independent sub-seeds of one texture seed, for the maps that combine several noises.
inline uint32_t sub_seed(uint32_t seed, uint32_t salt) {
    return hash_u32(seed ^ salt);
}

inline float cellular_feature_value(const CellularMap& m, const Vec3& q, uint32_t seed) {
    const CellularDistances d = cellular_3d(q, seed, m.metric);
    switch (m.feature) {
        case CellularFeature::F1:
            return glm::clamp(d.f1, 0.0f, 1.0f);
        case CellularFeature::F2:
            return glm::clamp(d.f2, 0.0f, 1.0f);
        case CellularFeature::F3:
            return glm::clamp(d.f3, 0.0f, 1.0f);
        case CellularFeature::F2MinusF1:
            return glm::clamp(d.f2 - d.f1, 0.0f, 1.0f);
        case CellularFeature::CellId:
            return unit_float(d.cell_id);
        case CellularFeature::Combination:
            break;
    }
    return cellular_combination(d);
}

// seed 003 "Pintar" (fig. 3.13), as a solid texture in units of the 64-pixel cell: two Worley
// maps of cell sizes 1 and 48/64, their x compressed by 0.6 as in the seed, displaced by two fBm
// maps (3 octaves, seed 003's y + 555 offset for the second), each value 2·F1/(F2+F3) squared,
// mixed 0.3/0.7. The seed displaced by fBm sampled once per pixel (a jitter of up to 7 of 64
// pixels); here the fBm is smooth at 4 lattice steps per cell and `warp` sets its amplitude.
inline float pool_bottom_value(const PoolBottomMap& m, const Vec3& q, uint32_t seed) {
    constexpr float kDisplacementFrequency = 4.0f;
    constexpr float kSmallCell = 48.0f / 64.0f;
    const FbmParams displacement{3, 0.5f, 2.0f};
    const Vec3 d = q * kDisplacementFrequency;
    const uint32_t disp_seed = sub_seed(seed, 65u);
    const float dx = 2.0f * m.warp * (fbm(d, displacement, disp_seed, NoiseBasis::Value) - 0.5f);
    const float dy =
        2.0f * m.warp *
        (fbm(d + Vec3(0.0f, 555.0f / 64.0f, 0.0f), displacement, disp_seed, NoiseBasis::Value) -
         0.5f);
    const float c1 = cellular_combination(
        cellular_3d(Vec3(q.x * 0.6f + dx, q.y + dy, q.z), sub_seed(seed, 15000u)));
    const float c2 = cellular_combination(
        cellular_3d(Vec3(q.x * 0.6f + dy, q.y + dx + 2312.0f / 64.0f, q.z) / kSmallCell,
                    sub_seed(seed, 8000u)));
    return glm::clamp(0.3f * c1 * c1 + 0.7f * c2 * c2, 0.0f, 1.0f);
}

struct ValueVisitor {
    const Vec3& q;
    uint32_t seed;

    float operator()(const ConstantMap&) const { return 0.0f; }
    float operator()(const ValueNoiseMap& m) const {
        return fbm(q, m.fbm, seed, NoiseBasis::Value);
    }
    float operator()(const PerlinMap& m) const {
        return 0.5f + 0.5f * fbm(q, m.fbm, seed, NoiseBasis::Gradient);
    }
    float operator()(const TurbulenceMap& m) const { return turbulence(q, m.fbm, seed); }
    float operator()(const CellularMap& m) const { return cellular_feature_value(m, q, seed); }
    float operator()(const MarbleMap& m) const {
        const float phase =
            2.0f * kPi * m.frequency * q.x + m.distortion * turbulence(q, m.fbm, seed);
        return 0.5f + 0.5f * std::sin(phase);
    }
    float operator()(const WarpedMap& m) const {
        // Quilez-style warping: three fBm fields displace the coordinates of a fourth.
        const Vec3 w(fbm(q, m.fbm, sub_seed(seed, 1u)),
                     fbm(q + Vec3(5.2f, 1.3f, 2.8f), m.fbm, sub_seed(seed, 2u)),
                     fbm(q + Vec3(1.7f, 9.2f, 4.1f), m.fbm, sub_seed(seed, 3u)));
        return glm::clamp(0.5f + 0.5f * fbm(q + m.warp * w, m.fbm, seed), 0.0f, 1.0f);
    }
    float operator()(const PoolBottomMap& m) const { return pool_bottom_value(m, q, seed); }
};

}  // namespace

ColorRamp::ColorRamp() : m_stops{{0.0f, Vec3(0.0f)}, {1.0f, Vec3(1.0f)}} {}

ColorRamp::ColorRamp(std::vector<ColorStop> stops) : m_stops(std::move(stops)) {
    if (m_stops.empty()) throw std::invalid_argument("a colour ramp needs at least one stop");
    std::stable_sort(m_stops.begin(), m_stops.end(), [](const ColorStop& a, const ColorStop& b) {
        return a.position < b.position;
    });
}

Vec3 ColorRamp::eval(float t) const {
    if (!(t > m_stops.front().position)) return m_stops.front().color;  // NaN too
    for (size_t i = 1; i < m_stops.size(); ++i) {
        const ColorStop& b = m_stops[i];
        if (t < b.position) {
            const ColorStop& a = m_stops[i - 1];
            const float u = (t - a.position) / (b.position - a.position);  // b.position > t ≥ a
            return a.color + (b.color - a.color) * u;                      // seed 003 InterLin
        }
    }
    return m_stops.back().color;
}

float srgb8_to_linear(int value) {
    const float c = static_cast<float>(glm::clamp(value, 0, 255)) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);  // IEC 61966-2-1
}

Vec3 srgb8_to_linear(int r, int g, int b) {
    return Vec3(srgb8_to_linear(r), srgb8_to_linear(g), srgb8_to_linear(b));
}

float Texture::value(const Vec3& p) const {
    const Vec3 q = p / scale;
    return std::visit(ValueVisitor{q, seed}, map);
}

Vec3 Texture::color(const Vec3& p) const {
    if (const auto* constant = std::get_if<ConstantMap>(&map)) return constant->color;
    return ramp.eval(value(p));
}

Vec3 Texture::gradient(const Vec3& p) const {
    if (std::holds_alternative<ConstantMap>(map)) return Vec3(0.0f);
    const float h = kGradientStep * scale;
    const float inv = 1.0f / (2.0f * h);
    return Vec3((value(p + Vec3(h, 0, 0)) - value(p - Vec3(h, 0, 0))) * inv,
                (value(p + Vec3(0, h, 0)) - value(p - Vec3(0, h, 0))) * inv,
                (value(p + Vec3(0, 0, h)) - value(p - Vec3(0, 0, h))) * inv);
}

const std::vector<std::string>& texture_kind_names() {
    static const std::vector<std::string> names = {"constant", "value",  "perlin", "turbulence",
                                                   "cellular", "marble", "warped", "pool-bottom"};
    return names;
}

std::string texture_kind_list() {
    std::string list;
    for (const std::string& n : texture_kind_names()) list += (list.empty() ? "" : ", ") + n;
    return list;
}

Texture make_texture(const std::string& kind) {
    Texture t;
    t.name = kind;
    if (kind == "constant") {
        t.map = ConstantMap{};
    } else if (kind == "value") {
        t.map = ValueNoiseMap{};
    } else if (kind == "perlin") {
        t.map = PerlinMap{};
        // fBm of gradient noise clusters around 0.5: the ramp spreads its middle.
        t.ramp = ColorRamp({{0.2f, Vec3(0.0f)}, {0.8f, Vec3(1.0f)}});
    } else if (kind == "turbulence") {
        t.map = TurbulenceMap{};
        t.ramp = ColorRamp({{0.0f, Vec3(0.0f)}, {0.6f, Vec3(1.0f)}});
    } else if (kind == "cellular") {
        t.map = CellularMap{};
    } else if (kind == "marble") {
        t.map = MarbleMap{};
        t.ramp = ColorRamp({{0.0f, srgb8_to_linear(60, 60, 72)},
                            {0.35f, srgb8_to_linear(200, 200, 205)},
                            {1.0f, srgb8_to_linear(245, 243, 238)}});
    } else if (kind == "warped") {
        t.map = WarpedMap{};
        t.ramp = ColorRamp({{0.2f, srgb8_to_linear(30, 20, 10)},
                            {0.5f, srgb8_to_linear(170, 110, 60)},
                            {0.8f, srgb8_to_linear(240, 220, 170)}});
    } else if (kind == "pool-bottom") {
        t.map = PoolBottomMap{};
        // seed 003 color_agua: RGB(40,100,162) at 0 to RGB(91,187,201) at 1 (display sRGB).
        t.ramp = ColorRamp(
            {{0.0f, srgb8_to_linear(40, 100, 162)}, {1.0f, srgb8_to_linear(91, 187, 201)}});
    } else {
        throw InputError(
            "", "unknown texture '" + kind + "' (expected one of: " + texture_kind_list() + ")");
    }
    return t;
}

Vec3 perturb_normal(const Vec3& normal, const Vec3& gradient, float strength,
                    const Vec3& facing_geometric) {
    const Vec3 tangential = gradient - glm::dot(gradient, normal) * normal;
    const Vec3 tilt = strength * tangential;
    if (!(glm::dot(tilt, tilt) > 0.0f) || !std::isfinite(tilt.x + tilt.y + tilt.z)) return normal;
    Vec3 n = glm::normalize(normal - tilt);
    // Keep the shading normal on the side the ray arrived from: lift it toward Ng if needed.
    const float c = glm::dot(n, facing_geometric);
    if (c < kMinBumpCosine) n = glm::normalize(n + (2.0f * kMinBumpCosine - c) * facing_geometric);
    return n;
}

Vec3 bump_normal(const Texture& texture, float strength, const Vec3& position, const Vec3& normal,
                 const Vec3& facing_geometric) {
    return perturb_normal(normal, texture.gradient(position) * texture.scale, strength,
                          facing_geometric);
}

Film texture_image(const Texture& texture, int width, int height, float pixels_per_unit) {
    Film film(width, height);
    int handoff = 0;  // TBB's ordering, stated for ThreadSanitizer (core/tsan_handoff.h)
    tsan_release(&handoff);
    tbb::parallel_for(0, height, [&](int j) {
        tsan_acquire(&handoff);
        const float y = (static_cast<float>(height - j) - 0.5f) / pixels_per_unit;
        for (int i = 0; i < width; ++i) {
            const float x = (static_cast<float>(i) + 0.5f) / pixels_per_unit;
            film.set(i, j, texture.color(Vec3(x, y, 0.0f)));
        }
        tsan_release(&handoff);
    });
    tsan_acquire(&handoff);
    return film;
}

}  // namespace rayo
