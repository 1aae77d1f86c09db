#include "core/sampling.h"

#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace rayo {

PixelOffset stratified_offset(uint32_t x, uint32_t y, uint32_t s, uint32_t spp,
                              uint32_t first_dimension, uint32_t first_sample) {
    if (spp <= 1) return {0.0f, 0.0f};
    // The grid's columns: the largest divisor of spp not above √spp, searched down from ⌊√spp⌋
    // (one division for a square count; an area light's 16 samples take this per sample).
    uint32_t root = static_cast<uint32_t>(std::sqrt(static_cast<double>(spp)));
    while (uint64_t(root) * root > spp) --root;
    while (uint64_t(root + 1) * (root + 1) <= spp) ++root;
    uint32_t columns = root;
    while (spp % columns != 0) --columns;
    const uint32_t rows = spp / columns;
    const uint32_t column = s % columns, row = s / columns;
    const float jitter_x = sample_uniform(x, y, first_sample + s, first_dimension),
                jitter_y = sample_uniform(x, y, first_sample + s, first_dimension + 1);
    // (column + jitter) rounds up to column + 1 in float for jitter = 1 − 2⁻²⁴: keep the offset
    // inside the pixel, [-0.5, 0.5).
    constexpr float kBelowHalf = 0.49999997f;
    return {std::min((static_cast<float>(column) + jitter_x) / static_cast<float>(columns) - 0.5f,
                     kBelowHalf),
            std::min((static_cast<float>(row) + jitter_y) / static_cast<float>(rows) - 0.5f,
                     kBelowHalf)};
}

glm::vec2 concentric_disk(const glm::vec2& u) {
    const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;  // the square [-1, 1]²
    if (a == 0.0f && b == 0.0f) return glm::vec2(0.0f);
    // Shirley–Chiu: the ring of half-side r = max(|a|, |b|) goes to the circle of radius r, the
    // position along the ring to the angle, linearly within each of the four triangles.
    float r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (kPi / 4.0f) * (b / a);
    } else {
        r = b;
        phi = kPi / 2.0f - (kPi / 4.0f) * (a / b);
    }
    return glm::vec2(r * std::cos(phi), r * std::sin(phi));
}

}  // namespace rayo
