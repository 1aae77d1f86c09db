#include "shading/noise.h"

#include <cmath>

namespace rayo {
namespace {

// Perlin's gradient selection (Perlin 2002): the 12 cube-edge directions, 4 of them twice, as a
// table (his bit-test form branches unpredictably: 4× slower here).
constexpr float kGradients[16][3] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0}, {1, -1, 0}, {-1, 1, 0}, {0, -1, -1}};

inline float grad_dot(uint32_t h, float x, float y, float z) {
    const float* g = kGradients[h & 15u];
    return g[0] * x + g[1] * y + g[2] * z;
}

// The lattice cell of p and the hashes of its 8 corners, chained as hash_3d does (the x and xy
// prefixes are shared by the corners: 14 mixes instead of 32).
struct CellCorners {
    Vec3 frac;
    uint32_t h[8];  // index = dx + 2·dy + 4·dz
};

inline CellCorners cell_corners(const Vec3& p, uint32_t seed) {
    const int32_t x = floor_to_int(p.x), y = floor_to_int(p.y), z = floor_to_int(p.z);
    CellCorners c;
    c.frac =
        Vec3(p.x - static_cast<float>(x), p.y - static_cast<float>(y), p.z - static_cast<float>(z));
    const uint32_t hs = hash_u32(seed);
    const uint32_t ux = static_cast<uint32_t>(x), uy = static_cast<uint32_t>(y),
                   uz = static_cast<uint32_t>(z);
    for (uint32_t dx = 0; dx < 2; ++dx) {
        const uint32_t hx = hash_u32(hs ^ (ux + dx));
        for (uint32_t dy = 0; dy < 2; ++dy) {
            const uint32_t hxy = hash_u32(hx ^ (uy + dy));
            c.h[dx + 2 * dy] = hash_u32(hxy ^ uz);
            c.h[dx + 2 * dy + 4] = hash_u32(hxy ^ (uz + 1u));
        }
    }
    return c;
}

inline float lerp(float a, float b, float t) {
    return a + (b - a) * t;
}

// Normalizes to [-1, 1]: the unscaled extreme of this gradient set is about 1.036 when all eight
// corner gradients line up (a hill-climbing search over 1.3M starts here reached 1.0043); the
// clamp keeps the documented range whatever the rounding.
constexpr float kGradientScale = 1.0f / 1.0365f;

}  // namespace

float smoothed_noise_2d(int32_t x, int32_t y, uint32_t seed) {
    const float corners = (int_noise_2d(x - 1, y - 1, seed) + int_noise_2d(x + 1, y - 1, seed) +
                           int_noise_2d(x - 1, y + 1, seed) + int_noise_2d(x + 1, y + 1, seed)) /
                          16.0f;
    const float sides = (int_noise_2d(x - 1, y, seed) + int_noise_2d(x + 1, y, seed) +
                         int_noise_2d(x, y - 1, seed) + int_noise_2d(x, y + 1, seed)) /
                        8.0f;
    const float centre = int_noise_2d(x, y, seed) / 4.0f;
    return corners + sides + centre;
}

float value_noise_2d(float x, float y, uint32_t seed) {
    const int32_t ix = floor_to_int(x), iy = floor_to_int(y);
    const float fx = x - static_cast<float>(ix), fy = y - static_cast<float>(iy);
    const float v00 = int_noise_2d(ix, iy, seed), v10 = int_noise_2d(ix + 1, iy, seed);
    const float v01 = int_noise_2d(ix, iy + 1, seed), v11 = int_noise_2d(ix + 1, iy + 1, seed);
    return interpolate(interpolate(v00, v10, fx), interpolate(v01, v11, fx), fy);
}

float smoothed_value_noise_2d(float x, float y, uint32_t seed) {
    const int32_t ix = floor_to_int(x), iy = floor_to_int(y);
    const float fx = x - static_cast<float>(ix), fy = y - static_cast<float>(iy);
    const float v1 = smoothed_noise_2d(ix, iy, seed), v2 = smoothed_noise_2d(ix + 1, iy, seed);
    const float v3 = smoothed_noise_2d(ix, iy + 1, seed);
    const float v4 = smoothed_noise_2d(ix + 1, iy + 1, seed);
    return interpolate(interpolate(v1, v2, fx), interpolate(v3, v4, fx), fy);
}

float value_noise_3d(const Vec3& p, uint32_t seed) {
    const CellCorners c = cell_corners(p, seed);
    const float sx = smooth_cubic(c.frac.x), sy = smooth_cubic(c.frac.y),
                sz = smooth_cubic(c.frac.z);
    float v[8];
    for (int i = 0; i < 8; ++i) v[i] = unit_float(c.h[i]);
    const float x00 = lerp(v[0], v[1], sx), x10 = lerp(v[2], v[3], sx);
    const float x01 = lerp(v[4], v[5], sx), x11 = lerp(v[6], v[7], sx);
    return lerp(lerp(x00, x10, sy), lerp(x01, x11, sy), sz);
}

float gradient_noise_3d(const Vec3& p, uint32_t seed) {
    const CellCorners c = cell_corners(p, seed);
    const float x = c.frac.x, y = c.frac.y, z = c.frac.z;
    const float sx = smooth_quintic(x), sy = smooth_quintic(y), sz = smooth_quintic(z);
    const float g000 = grad_dot(c.h[0], x, y, z), g100 = grad_dot(c.h[1], x - 1, y, z);
    const float g010 = grad_dot(c.h[2], x, y - 1, z), g110 = grad_dot(c.h[3], x - 1, y - 1, z);
    const float g001 = grad_dot(c.h[4], x, y, z - 1), g101 = grad_dot(c.h[5], x - 1, y, z - 1);
    const float g011 = grad_dot(c.h[6], x, y - 1, z - 1);
    const float g111 = grad_dot(c.h[7], x - 1, y - 1, z - 1);
    const float n = lerp(lerp(lerp(g000, g100, sx), lerp(g010, g110, sx), sy),
                         lerp(lerp(g001, g101, sx), lerp(g011, g111, sx), sy), sz);
    return glm::clamp(n * kGradientScale, -1.0f, 1.0f);
}

float fbm(const Vec3& p, const FbmParams& params, uint32_t seed, NoiseBasis basis) {
    const int octaves = glm::clamp(params.octaves, 1, kMaxOctaves);
    float sum = 0.0f, norm = 0.0f, amplitude = 1.0f, frequency = 1.0f;
    for (int i = 0; i < octaves; ++i) {
        const Vec3 q = p * frequency;
        const uint32_t s = octave_seed(seed, i);
        const float n = basis == NoiseBasis::Value ? value_noise_3d(q, s) : gradient_noise_3d(q, s);
        sum += amplitude * n;
        norm += amplitude;
        amplitude *= params.persistence;
        frequency *= params.lacunarity;  // 2^i exactly for the default lacunarity 2
    }
    return norm > 0.0f ? sum / norm : 0.0f;
}

float fbm_2d(float x, float y, const FbmParams& params, uint32_t seed) {
    const int octaves = glm::clamp(params.octaves, 1, kMaxOctaves);
    float sum = 0.0f, norm = 0.0f, amplitude = 1.0f, frequency = 1.0f;
    for (int i = 0; i < octaves; ++i) {
        sum +=
            amplitude * smoothed_value_noise_2d(x * frequency, y * frequency, octave_seed(seed, i));
        norm += amplitude;
        amplitude *= params.persistence;
        frequency *= params.lacunarity;
    }
    return norm > 0.0f ? sum / norm : 0.0f;
}

float turbulence(const Vec3& p, const FbmParams& params, uint32_t seed) {
    const int octaves = glm::clamp(params.octaves, 1, kMaxOctaves);
    float sum = 0.0f, norm = 0.0f, amplitude = 1.0f, frequency = 1.0f;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * std::fabs(gradient_noise_3d(p * frequency, octave_seed(seed, i)));
        norm += amplitude;
        amplitude *= params.persistence;
        frequency *= params.lacunarity;
    }
    return norm > 0.0f ? sum / norm : 0.0f;
}

}  // namespace rayo
