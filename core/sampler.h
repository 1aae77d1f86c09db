#pragma once
// The sampler of the tile loop's contract (core/render.h): a sample is a pure function of the
// pixel, the sample index and the dimension (the stateless hash of core/sampling.h), so every
// image is the same bits for any thread count, tile size, MPI rank count and resume
// (docs/architecture.md, "Hot-path rules"). Dimensions 0-1 are the film position and 2-3 the
// lens (both drawn by the tile loop); integrators draw from kFirstIntegratorDimension on.
#include <cstdint>
#include <glm/vec2.hpp>

#include "core/sampling.h"

namespace rayo {

constexpr uint32_t kFirstIntegratorDimension = kLensDimension + 2;

struct PixelSample {
    uint32_t x = 0, y = 0;  // the pixel (adaptive antialiasing: the lattice point)
    uint32_t index = 0;     // the sample's index in its pixel
    uint32_t count = 1;     // samples per pixel

    float get1d(uint32_t dimension) const { return sample_uniform(x, y, index, dimension); }
    glm::vec2 get2d(uint32_t dimension) const {
        return glm::vec2(sample_uniform(x, y, index, dimension),
                         sample_uniform(x, y, index, dimension + 1));
    }
    // Point k of n in [0,1)² for the dimension pair `dimension`, stratified over the n points
    // (one jittered point per cell of core/sampling.h's stratified grid): for an integrator that
    // spends n rays of one kind per camera sample (ambient occlusion's hemisphere). One point
    // is get2d's.
    glm::vec2 stratified2d(uint32_t dimension, uint32_t k, uint32_t n) const {
        if (n <= 1) return get2d(dimension);
        const uint32_t key = hash_combine(hash_combine(hash_u32(x), y), index);
        const PixelOffset o = stratified_offset(key, dimension, k, n);
        return glm::vec2(o.dx + 0.5f, o.dy + 0.5f);
    }
};

}  // namespace rayo
