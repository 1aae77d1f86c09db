#pragma once
// The float RGBA film: scene-linear Rec.709 radiance, row 0 at the top, the whole image in
// memory. The first tile sink (core/tile_sink.h): tiles are copied in as they finish, from many
// threads into disjoint pixels; nothing here locks.
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "core/tile_sink.h"

namespace rayo {

// The largest in-memory film: 2^28 pixels (e.g. 16384 × 16384), 4 GiB of float RGBA. Larger
// renders stream to their file (core/image/tile_stream.h); the preview and `rayo texture`, which
// draw into a film, stop here.
constexpr long long kMaxFilmPixels = 1LL << 28;

// InputError(where) when a width × height film would exceed kMaxFilmPixels.
inline void check_film_size(int width, int height, const std::string& where) {
    const long long pixels = static_cast<long long>(width) * height;
    if (pixels > kMaxFilmPixels) {
        throw InputError(where, std::to_string(width) + "x" + std::to_string(height) +
                                    " is too large for an in-memory image (at most " +
                                    std::to_string(kMaxFilmPixels) +
                                    " pixels, 4 GiB); only `rayo render` goes beyond, "
                                    "streaming to its output file");
    }
}

class Film : public TileSink {
  public:
    Film(int width, int height)
        : m_width(width), m_height(height), m_rgba(static_cast<size_t>(width) * height * 4, 0.0f) {}

    void write_tile(const Tile& tile, const float* rgba) override {
        for (int row = 0; row < tile.height; ++row) {
            const float* source = rgba + static_cast<size_t>(row) * tile.width * 4;
            float* target = &m_rgba[(static_cast<size_t>(tile.y0 + row) * m_width + tile.x0) * 4];
            std::copy(source, source + static_cast<size_t>(tile.width) * 4, target);
        }
    }

    int width() const { return m_width; }
    int height() const { return m_height; }
    void set(int x, int y, const Vec3& rgb, float alpha = 1.0f) {
        float* p = &m_rgba[(static_cast<size_t>(y) * m_width + x) * 4];
        p[0] = rgb.x;
        p[1] = rgb.y;
        p[2] = rgb.z;
        p[3] = alpha;
    }
    Vec3 rgb(int x, int y) const {
        const float* p = &m_rgba[(static_cast<size_t>(y) * m_width + x) * 4];
        return Vec3(p[0], p[1], p[2]);
    }
    const std::vector<float>& rgba() const { return m_rgba; }
    std::vector<float>& rgba() { return m_rgba; }

  private:
    int m_width, m_height;
    std::vector<float> m_rgba;
};

}  // namespace rayo
