#pragma once
// Stateless random numbers: every value is a hash of (pixel, sample, dimension, frame), so the
// image does not depend on the thread count or tile order (docs/architecture.md "Hot-path rules").
#include <cstdint>
#include <glm/vec2.hpp>

namespace rayo {

// A 32-bit integer finaliser (the "lowbias32" constants of Chris Wellons' hash prospector).
inline uint32_t hash_u32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

inline uint32_t hash_combine(uint32_t seed, uint32_t value) {
    return hash_u32(seed ^ (value + 0x9e3779b9U + (seed << 6) + (seed >> 2)));
}

// Uniform in [0, 1): the top 24 bits of the hash.
inline float sample_uniform(uint32_t x, uint32_t y, uint32_t sample, uint32_t dimension,
                            uint32_t frame = 0) {
    uint32_t h = hash_u32(x);
    h = hash_combine(h, y);
    h = hash_combine(h, sample);
    h = hash_combine(h, dimension);
    h = hash_combine(h, frame);
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

// Stratified sub-pixel offset in [-0.5, 0.5)² for sample `s` of `spp`: the pixel is split into
// columns × rows strata (columns the largest divisor of spp not above √spp), one jittered sample
// each. One sample per pixel goes through the pixel centre. The jitter uses hash dimensions
// first_dimension and first_dimension + 1: 0 for the film position, kLensDimension for the lens.
// A progressive render's later passes (core/progressive.h) stratify each pass's spp samples
// alike but hash the sample's index in the whole render, first_sample + s, so that no two
// passes repeat a jitter; first_sample 0 is a plain render's sample set.
struct PixelOffset {
    float dx, dy;
};
PixelOffset stratified_offset(uint32_t x, uint32_t y, uint32_t s, uint32_t spp,
                              uint32_t first_dimension = 0, uint32_t first_sample = 0);

// The lens sample of sample `s` of pixel (x, y), in [0, 1)²: stratified like the film position
// but from its own hash dimensions; the lens centre (0.5, 0.5) at one sample per pixel.
constexpr uint32_t kLensDimension = 2;
inline glm::vec2 lens_sample(uint32_t x, uint32_t y, uint32_t s, uint32_t spp,
                             uint32_t first_sample = 0) {
    const PixelOffset o = stratified_offset(x, y, s, spp, kLensDimension, first_sample);
    return glm::vec2(o.dx + 0.5f, o.dy + 0.5f);
}

// The unit square [0, 1)² onto the unit disk, area-preserving and keeping strata compact: the
// concentric map of Shirley and Chiu, "A Low Distortion Map Between Disk and Square" (1997).
// Square rings go to circles; (0.5, 0.5) goes to the centre.
glm::vec2 concentric_disk(const glm::vec2& u);

}  // namespace rayo
