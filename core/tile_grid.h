#pragma once
// The image as a fixed grid of square tiles (the last row and column may be narrower), numbered
// row-major from the top left. The grid is the unit of work of the tile loop, of resuming and of
// MPI distribution, and the unit every sink receives (core/tile_sink.h). The default size, 64,
// is OpenEXR's customary tile size, so that a tiled EXR sink can write each tile as one EXR tile.
#include <algorithm>
#include <cstddef>
#include <string>

#include "core/error.h"

namespace rayo {

constexpr int kDefaultTileSize = 64;
// Tile sizes are multiples of the coherent block (core/render.h batches camera rays by the
// image's 16×16 blocks), so that the image's bits do not depend on the tile size.
constexpr int kCoherentBlock = 16;
constexpr int kMaxTileSize = 4096;
inline bool valid_tile_size(int size) {
    return size >= kCoherentBlock && size <= kMaxTileSize && size % kCoherentBlock == 0;
}
inline std::string tile_size_expectation() {
    return "a multiple of " + std::to_string(kCoherentBlock) + " in [" +
           std::to_string(kCoherentBlock) + ", " + std::to_string(kMaxTileSize) + "]";
}

struct Tile {
    int index = 0;
    int x0 = 0, y0 = 0;  // top-left pixel
    int width = 0, height = 0;

    size_t pixel_count() const { return static_cast<size_t>(width) * height; }
};

class TileGrid {
  public:
    TileGrid(int image_width, int image_height, int tile_size = kDefaultTileSize)
        : m_width(image_width),
          m_height(image_height),
          m_tile_size(checked_tile_size(tile_size)),
          m_columns((image_width + m_tile_size - 1) / m_tile_size),
          m_rows((image_height + m_tile_size - 1) / m_tile_size) {}

    int image_width() const { return m_width; }
    int image_height() const { return m_height; }
    int tile_size() const { return m_tile_size; }
    int columns() const { return m_columns; }
    int rows() const { return m_rows; }
    int tile_count() const { return m_columns * m_rows; }

    Tile tile(int index) const {
        Tile t;
        t.index = index;
        t.x0 = (index % m_columns) * m_tile_size;
        t.y0 = (index / m_columns) * m_tile_size;
        t.width = std::min(m_tile_size, m_width - t.x0);
        t.height = std::min(m_tile_size, m_height - t.y0);
        return t;
    }

  private:
    static int checked_tile_size(int size) {
        if (!valid_tile_size(size)) {
            throw InputError("tile size", "expected " + tile_size_expectation() + ", got " +
                                              std::to_string(size));
        }
        return size;
    }

    int m_width, m_height, m_tile_size, m_columns, m_rows;
};

}  // namespace rayo
