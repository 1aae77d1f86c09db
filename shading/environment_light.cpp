#include "shading/environment_light.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/math.h"

namespace rayo {

namespace {

constexpr float kTwoPi = 2.0f * kPi;

// (u, v) of a unit direction in the image's frame (the mapping in the header).
void direction_to_uv(const Vec3& d, float& u, float& v) {
    u = 0.5f + std::atan2(d.x, -d.z) / kTwoPi;
    u = u - std::floor(u);
    if (u >= 1.0f) u = 0.0f;
    v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
}

Vec3 uv_to_direction(float u, float v, float& sin_theta) {
    const float theta = v * kPi, phi = (u - 0.5f) * kTwoPi;
    sin_theta = std::sin(theta);
    return Vec3(sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi));
}

}  // namespace

EnvironmentMap::EnvironmentMap(int width, int height, std::vector<Vec3> texels)
    : m_width(width), m_height(height), m_texels(std::move(texels)) {
    // Each texel's weight: its largest channel (so every texel that emits at all can be
    // sampled: the estimator stays unbiased) times the solid angle of its row, ∝ sin θ.
    std::vector<float> weights(m_texels.size());
    for (int y = 0; y < height; ++y) {
        const float sin_theta = std::sin(kPi * (static_cast<float>(y) + 0.5f) / height);
        for (int x = 0; x < width; ++x) {
            const Vec3& c = m_texels[size_t(y) * size_t(width) + size_t(x)];
            weights[size_t(y) * size_t(width) + size_t(x)] = std::max({c.x, c.y, c.z}) * sin_theta;
        }
    }
    m_distribution = PiecewiseConstant2D(weights, size_t(width), size_t(height));
}

Vec3 EnvironmentMap::lookup(float u, float v) const {
    const int x = std::clamp(static_cast<int>(u * static_cast<float>(m_width)), 0, m_width - 1);
    const int y = std::clamp(static_cast<int>(v * static_cast<float>(m_height)), 0, m_height - 1);
    return m_texels[size_t(y) * size_t(m_width) + size_t(x)];
}

Vec3 EnvironmentLight::to_image(const Vec3& d) const {
    if (rotation == 0.0f) return d;
    const float a = glm::radians(rotation), c = std::cos(a), s = std::sin(a);
    // The inverse of the rotation by `rotation` about +y.
    return Vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

Vec3 EnvironmentLight::from_image(const Vec3& d) const {
    if (rotation == 0.0f) return d;
    const float a = glm::radians(rotation), c = std::cos(a), s = std::sin(a);
    return Vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

Vec3 EnvironmentLight::radiance(const Vec3& direction) const {
    const Vec3 scale = color * intensity;
    if (!map) return scale;
    float u, v;
    direction_to_uv(to_image(direction), u, v);
    return scale * map->lookup(u, v);
}

bool EnvironmentLight::sample(const Vec3& /*point*/, const glm::vec2& u, LightSample& out) const {
    out.distance = std::numeric_limits<float>::infinity();
    if (!map) {
        // Uniform over the sphere: z = 1 − 2u, pdf 1/4π.
        const float z = 1.0f - 2.0f * u.x;
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const float phi = kTwoPi * u.y;
        out.direction = Vec3(r * std::cos(phi), z, r * std::sin(phi));
        out.radiance = color * intensity;
        out.pdf = 1.0f / (4.0f * kPi);
        return out.radiance != Vec3(0.0f);
    }
    float s, t, density;
    map->sample(u.x, u.y, s, t, density);
    float sin_theta;
    const Vec3 local = uv_to_direction(s, t, sin_theta);
    if (!(density > 0.0f) || !(sin_theta > 0.0f)) return false;
    out.direction = from_image(local);
    out.radiance = color * intensity * map->lookup(s, t);
    // From area in [0,1)² to solid angle: dω = 2π·π·sin θ du dv.
    out.pdf = density / (kTwoPi * kPi * sin_theta);
    return out.radiance != Vec3(0.0f);
}

float EnvironmentLight::pdf(const Vec3& /*point*/, const Vec3& direction) const {
    if (!map) return 1.0f / (4.0f * kPi);
    const Vec3 local = to_image(direction);
    float u, v;
    direction_to_uv(local, u, v);
    const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - local.y * local.y));
    if (!(sin_theta > 0.0f)) return 0.0f;
    return map->density(u, v) / (kTwoPi * kPi * sin_theta);
}

}  // namespace rayo
