#pragma once
// The float RGBA film: scene-linear Rec.709 radiance, row 0 at the top, the whole image in
// memory. The first tile sink (core/tile_sink.h): tiles are copied in as they finish, from many
// threads into disjoint pixels; nothing here locks.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/math.h"
#include "core/tile_sink.h"

namespace rayo {

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
