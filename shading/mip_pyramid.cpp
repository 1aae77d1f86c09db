#include "shading/mip_pyramid.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace rayo {
namespace {

float unit(uint8_t value) {
    return static_cast<float>(value) * (1.0f / 255.0f);
}
float unit(float value) {
    return value;
}

template <typename T>
T stored(float value) {
    if constexpr (std::is_same_v<T, uint8_t>) {
        // Rounded to nearest (the value is ≥ 0 after the clamp).
        return static_cast<uint8_t>(std::clamp(value, 0.0f, 255.0f) + 0.5f);
    } else {
        return value;
    }
}

// The source texels a texel of a level of `to` texels covers in one of `from` (to = from / 2,
// at least 1): texel i spans [i·from/to, (i+1)·from/to), each source texel weighted by its
// overlap (two halves for an even size; an odd size spreads its extra texel over its
// neighbours), the weights summing to 1.
struct Tap {
    int index;
    float weight;
};
std::vector<std::vector<Tap>> box_taps(int from, int to) {
    std::vector<std::vector<Tap>> taps(static_cast<size_t>(to));
    const double span = double(from) / double(to);
    for (int i = 0; i < to; ++i) {
        const double begin = i * span, end = (i + 1) * span;
        for (int j = static_cast<int>(std::floor(begin)); j < from && j < end; ++j) {
            const double overlap = std::min(end, double(j + 1)) - std::max(begin, double(j));
            if (overlap > 0.0)
                taps[static_cast<size_t>(i)].push_back({j, static_cast<float>(overlap / span)});
        }
    }
    return taps;
}

// Coordinate s of an image side as the wrap mode reads it: [0, 1) repeating, [0, 1] clamped,
// [0, 2) mirrored (the second unit mirrored by wrap_index); 0 for a coordinate that is no number.
float wrapped_coordinate(float s, TextureWrap wrap) {
    if (!std::isfinite(s)) return 0.0f;
    switch (wrap) {
        case TextureWrap::Clamp:
            return std::clamp(s, 0.0f, 1.0f);
        case TextureWrap::Mirror:
            return s - 2.0f * std::floor(0.5f * s);
        case TextureWrap::Repeat:
            break;
    }
    return s - std::floor(s);
}

// Texel i of a side of n texels under the wrap mode; i lies within a few texels of
// [0, n) (repeat, clamp) or [0, 2n) (mirror) after wrapped_coordinate.
int wrap_index(int i, int n, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::Clamp:
            return std::clamp(i, 0, n - 1);
        case TextureWrap::Mirror: {
            const int period = 2 * n;
            while (i < 0) i += period;
            while (i >= period) i -= period;
            return i < n ? i : period - 1 - i;
        }
        case TextureWrap::Repeat:
            break;
    }
    while (i < 0) i += n;
    while (i >= n) i -= n;
    return i;
}

// The uniform cubic B-spline's weights of the four texels around a point at fraction f past the
// second (OpenImageIO's bicubic texture filter is this spline).
void bspline_weights(float f, float w[4]) {
    const float f2 = f * f, f3 = f2 * f;
    w[0] = (1.0f - 3.0f * f + 3.0f * f2 - f3) * (1.0f / 6.0f);
    w[1] = (4.0f - 6.0f * f2 + 3.0f * f3) * (1.0f / 6.0f);
    w[2] = (1.0f + 3.0f * f + 3.0f * f2 - 3.0f * f3) * (1.0f / 6.0f);
    w[3] = f3 * (1.0f / 6.0f);
}

}  // namespace

MipPyramid::MipPyramid(int width, int height, int channels, const uint8_t* pixels) {
    build(width, height, channels, pixels);
}

MipPyramid::MipPyramid(int width, int height, int channels, const float* pixels)
    : m_floating(true) {
    build(width, height, channels, pixels);
}

size_t MipPyramid::bytes_for(int width, int height, bool floating) {
    size_t texels = 0;
    for (size_t w = size_t(std::max(width, 1)), h = size_t(std::max(height, 1));;
         w = std::max<size_t>(w / 2, 1), h = std::max<size_t>(h / 2, 1)) {
        texels += w * h;
        if (w == 1 && h == 1) break;
    }
    return texels * 4 * (floating ? sizeof(float) : 1);
}

size_t MipPyramid::bytes() const {
    return m_bytes.size() + m_floats.size() * sizeof(float);
}

template <typename T>
void MipPyramid::build(int width, int height, int channels, const T* pixels) {
    std::vector<T>& texels = [this]() -> std::vector<T>& {
        if constexpr (std::is_same_v<T, uint8_t>) {
            return m_bytes;
        } else {
            return m_floats;
        }
    }();
    width = std::max(width, 1);
    height = std::max(height, 1);
    texels.resize(bytes_for(width, height, m_floating) / sizeof(T));
    // Level 0 as RGBA.
    const T opaque = std::is_same_v<T, uint8_t> ? T(255) : T(1);
    const size_t count = size_t(width) * size_t(height);
    for (size_t i = 0; i < count; ++i) {
        const T* in = pixels + i * size_t(channels);
        T* out = texels.data() + i * 4;
        if (channels <= 2) {
            out[0] = out[1] = out[2] = in[0];
            out[3] = channels == 2 ? in[1] : opaque;
        } else {
            out[0] = in[0];
            out[1] = in[1];
            out[2] = in[2];
            out[3] = channels >= 4 ? in[3] : opaque;
        }
    }
    m_levels.push_back({width, height, 0});
    // Each next level: the box filter over the texels each of its texels covers.
    while (m_levels.back().width > 1 || m_levels.back().height > 1) {
        const Level from = m_levels.back();
        Level to{std::max(from.width / 2, 1), std::max(from.height / 2, 1),
                 from.offset + size_t(from.width) * size_t(from.height)};
        if (from.width == 2 * to.width && from.height == 2 * to.height) {
            // Even sides: each texel the mean of a 2 × 2 block (the taps below would give the
            // same, in the same order).
            const T* source = texels.data() + from.offset * 4;
            T* target = texels.data() + to.offset * 4;
            const size_t row = size_t(from.width) * 4;
            for (int y = 0; y < to.height; ++y) {
                const T* above = source + size_t(2 * y) * row;
                const T* below = above + row;
                for (int x = 0; x < to.width; ++x, target += 4) {
                    const size_t at = size_t(8 * x);
                    for (int c = 0; c < 4; ++c) {
                        float sum = 0.0f;
                        sum += 0.25f * static_cast<float>(above[at + c]);
                        sum += 0.25f * static_cast<float>(above[at + 4 + c]);
                        sum += 0.25f * static_cast<float>(below[at + c]);
                        sum += 0.25f * static_cast<float>(below[at + 4 + c]);
                        target[c] = stored<T>(sum);
                    }
                }
            }
            m_levels.push_back(to);
            continue;
        }
        const auto taps_x = box_taps(from.width, to.width);
        const auto taps_y = box_taps(from.height, to.height);
        for (int y = 0; y < to.height; ++y) {
            for (int x = 0; x < to.width; ++x) {
                float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
                for (const Tap& ty : taps_y[size_t(y)]) {
                    for (const Tap& tx : taps_x[size_t(x)]) {
                        const T* in =
                            texels.data() + (from.offset + size_t(ty.index) * size_t(from.width) +
                                             size_t(tx.index)) *
                                                4;
                        const float w = ty.weight * tx.weight;
                        for (int c = 0; c < 4; ++c) sum[c] += w * static_cast<float>(in[c]);
                    }
                }
                T* out = texels.data() + (to.offset + size_t(y) * size_t(to.width) + size_t(x)) * 4;
                for (int c = 0; c < 4; ++c) out[c] = stored<T>(sum[c]);
            }
        }
        m_levels.push_back(to);
    }
}

glm::vec4 MipPyramid::texel(int level, int x, int y) const {
    const Level& l = m_levels[static_cast<size_t>(level)];
    const size_t at = (l.offset + size_t(y) * size_t(l.width) + size_t(x)) * 4;
    if (m_floating)
        return glm::vec4(m_floats[at], m_floats[at + 1], m_floats[at + 2], m_floats[at + 3]);
    return glm::vec4(unit(m_bytes[at]), unit(m_bytes[at + 1]), unit(m_bytes[at + 2]),
                     unit(m_bytes[at + 3]));
}

template <typename T>
glm::vec4 MipPyramid::sample(const T* texels, const Level& level, float s, float t,
                             TextureWrap wrap_s, TextureWrap wrap_t, TextureFilter filter) const {
    // Texel centres at half-integers: x = s·width − 1/2.
    const float x = wrapped_coordinate(s, wrap_s) * static_cast<float>(level.width) - 0.5f;
    const float y = wrapped_coordinate(t, wrap_t) * static_cast<float>(level.height) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
    const T* base = texels + level.offset * 4;
    const size_t row = size_t(level.width);
    const auto fetch = [&](int column, size_t line) {
        const T* p = base + (line * row + size_t(column)) * 4;
        return glm::vec4(unit(p[0]), unit(p[1]), unit(p[2]), unit(p[3]));
    };
    if (filter == TextureFilter::Bicubic) {
        float wx[4], wy[4];
        bspline_weights(fx, wx);
        bspline_weights(fy, wy);
        int columns[4];
        for (int i = 0; i < 4; ++i) columns[i] = wrap_index(ix - 1 + i, level.width, wrap_s);
        glm::vec4 sum(0.0f);
        for (int j = 0; j < 4; ++j) {
            const size_t line = size_t(wrap_index(iy - 1 + j, level.height, wrap_t));
            glm::vec4 across(0.0f);
            for (int i = 0; i < 4; ++i) across += wx[i] * fetch(columns[i], line);
            sum += wy[j] * across;
        }
        return sum;
    }
    const int x_0 = wrap_index(ix, level.width, wrap_s);
    const int x_1 = wrap_index(ix + 1, level.width, wrap_s);
    const size_t y_0 = size_t(wrap_index(iy, level.height, wrap_t));
    const size_t y_1 = size_t(wrap_index(iy + 1, level.height, wrap_t));
    const glm::vec4 top = fetch(x_0, y_0) + fx * (fetch(x_1, y_0) - fetch(x_0, y_0));
    const glm::vec4 bottom = fetch(x_0, y_1) + fx * (fetch(x_1, y_1) - fetch(x_0, y_1));
    return top + fy * (bottom - top);
}

glm::vec4 MipPyramid::sample_level(int level, float s, float t, TextureWrap wrap_s,
                                   TextureWrap wrap_t, TextureFilter filter) const {
    const Level& l = m_levels[static_cast<size_t>(std::clamp(level, 0, levels() - 1))];
    return m_floating ? sample(m_floats.data(), l, s, t, wrap_s, wrap_t, filter)
                      : sample(m_bytes.data(), l, s, t, wrap_s, wrap_t, filter);
}

glm::vec4 MipPyramid::lookup(float s, float t, float width, TextureWrap wrap_s, TextureWrap wrap_t,
                             TextureFilter filter) const {
    // Williams 1983: the level whose texel spans the footprint, log2 of the footprint in texels
    // of level 0 along the image's larger side (so neither side aliases).
    const float texels =
        width * static_cast<float>(std::max(m_levels[0].width, m_levels[0].height));
    if (!(texels > 1.0f)) return sample_level(0, s, t, wrap_s, wrap_t, filter);
    const float lod = std::log2(texels);
    const int last = levels() - 1;
    if (!(lod < static_cast<float>(last))) return sample_level(last, s, t, wrap_s, wrap_t, filter);
    const int below = static_cast<int>(lod);
    const float blend = lod - static_cast<float>(below);
    const glm::vec4 fine = sample_level(below, s, t, wrap_s, wrap_t, filter);
    const glm::vec4 coarse = sample_level(below + 1, s, t, wrap_s, wrap_t, filter);
    return fine + blend * (coarse - fine);
}

}  // namespace rayo
