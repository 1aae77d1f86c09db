#pragma once
// Lattice noise of seed 003 ch. 3: the integer hash ("IntNoise"), the smooth interpolants, the
// seed's smoothed 2-D value noise, 3-D value and gradient (Perlin) noise, fBm and turbulence.
// Pure functions of (position, seed): deterministic, thread-safe, no allocation.
#include <cstdint>

#include "core/math.h"
#include "core/sampling.h"

namespace rayo {

// hash_u32 (core/sampling.h, lowbias32) is the integer mixer: every input bit flips each output
// bit with probability ~1/2. That is the intent of seed 003's IntNoise: a different generator per
// seed and no visible lattice pattern.

// Hash of an integer lattice point and a seed (chained, so x, y, z and seed never cancel).
inline uint32_t hash_2d(int32_t x, int32_t y, uint32_t seed) {
    return hash_u32(hash_u32(hash_u32(seed) ^ static_cast<uint32_t>(x)) ^ static_cast<uint32_t>(y));
}
inline uint32_t hash_3d(int32_t x, int32_t y, int32_t z, uint32_t seed) {
    return hash_u32(hash_2d(x, y, seed) ^ static_cast<uint32_t>(z));
}

// The top 24 bits of a hash as a float in [0, 1).
inline float unit_float(uint32_t h) {
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

// seed 003 IntNoise(n): a value in [0, 1) that depends on every bit of n.
inline float int_noise(int32_t n) {
    return unit_float(hash_u32(static_cast<uint32_t>(n)));
}
// seed 003 IntNoise2D(x, y), fixed: the hash of the lattice point (the printed code hashed x only
// and folded y in as x + 57·y, which repeats along a line).
inline float int_noise_2d(int32_t x, int32_t y, uint32_t seed) {
    return unit_float(hash_2d(x, y, seed));
}
inline float int_noise_3d(int32_t x, int32_t y, int32_t z, uint32_t seed) {
    return unit_float(hash_3d(x, y, z, seed));
}

// seed 003 "InterPolacion": 3x² − 2x³ (C¹ at the lattice), and Perlin's quintic 6x⁵ − 15x⁴ + 10x³
// (C², used by the gradient noise so its bump-map gradient is continuous).
inline float smooth_cubic(float t) {
    return t * t * (3.0f - 2.0f * t);
}
inline float smooth_quintic(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}
inline float interpolate(float a, float b, float x) {
    return a + (b - a) * smooth_cubic(x);
}

// floor() as an int, for negative coordinates too (seed 003's int(x) truncates toward zero and
// mirrors the lattice around 0). Clamped to ±2^30 so that huge inputs cannot overflow.
inline int32_t floor_to_int(float x) {
    constexpr float kLimit = 1073741824.0f;
    x = glm::clamp(x, -kLimit, kLimit);
    const int32_t i = static_cast<int32_t>(x);
    return x < static_cast<float>(i) ? i - 1 : i;
}

// seed 003 SmoothNoise2D: centre/4 + sides/8 + corners/16 of int_noise_2d; in [0, 1).
float smoothed_noise_2d(int32_t x, int32_t y, uint32_t seed);

// 2-D value noise in [0, 1]: int_noise_2d at the lattice, blended with smooth_cubic.
float value_noise_2d(float x, float y, uint32_t seed);
// seed 003 InterpolatedNoise2D: the same blend over smoothed_noise_2d (floor, not truncation).
float smoothed_value_noise_2d(float x, float y, uint32_t seed);

// 3-D value noise in [0, 1] (trilinear blend with smooth_cubic).
float value_noise_3d(const Vec3& p, uint32_t seed);

// 3-D gradient noise (Perlin 2002: 12 edge gradients, quintic fade), 0 at every lattice point.
// Scaled so that the result lies in [-1, 1] (the unscaled extreme is below 1.04; clamped).
float gradient_noise_3d(const Vec3& p, uint32_t seed);

enum class NoiseBasis {
    Value,     // value_noise_3d, in [0, 1]
    Gradient,  // gradient_noise_3d, in [-1, 1]
};

// Octave i samples the basis at frequency lacunarity^i with amplitude persistence^i (seed 003:
// frequency 2^i; the printed `2^i` is XOR in C, and its persistence 2 let the finest octave
// dominate, so the default is 1/2).
struct FbmParams {
    int octaves = 6;
    float persistence = 0.5f;
    float lacunarity = 2.0f;
};
constexpr int kMaxOctaves = 16;

// The seed each octave uses, so that octaves are independent noises.
inline uint32_t octave_seed(uint32_t seed, int octave) {
    return hash_u32(seed + 0x9e3779b9u * static_cast<uint32_t>(octave + 1));
}

// fBm: Σ a_i·noise_i(p·f_i) / Σ a_i, so the result keeps the basis's range ([0, 1] for Value,
// [-1, 1] for Gradient). Octaves are clamped to [1, kMaxOctaves].
float fbm(const Vec3& p, const FbmParams& params, uint32_t seed,
          NoiseBasis basis = NoiseBasis::Gradient);

// The seed's PerlinNoise2D with its fixes: fbm of smoothed_value_noise_2d, normalized to [0, 1].
float fbm_2d(float x, float y, const FbmParams& params, uint32_t seed);

// Perlin's turbulence: Σ a_i·|gradient_i(p·f_i)| / Σ a_i, in [0, 1].
float turbulence(const Vec3& p, const FbmParams& params, uint32_t seed);

}  // namespace rayo
