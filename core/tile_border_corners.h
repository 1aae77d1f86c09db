#pragma once
// The pixel corners that lie on the borders between tiles, traced once for the whole image:
// with `aa` = "corners" (core/adaptive_aa.h) every pixel is the mean of its four corners, and a
// corner on a tile border belongs to two (or four) tiles. Each tile asks here for those corners;
// the first tile to ask traces it, the others take its value, so the image takes exactly
// (W + 1) × (H + 1) camera rays (the SPD's testing procedure, rule 6: 513 × 513 rays for
// 512 × 512 pixels; docs/antialiasing.md). A corner's value depends only on its place, so which
// tile traces it changes nothing in the image. Only the border lines are held: 2/tile_size of the
// corners of the image.
#include <atomic>
#include <memory>
#include <thread>

#include "core/tile_grid.h"

namespace rayo {

template <typename Sample>
class TileBorderCorners {
  public:
    explicit TileBorderCorners(const TileGrid& grid)
        : m_tile(grid.tile_size()),
          m_width(grid.image_width()),
          m_height(grid.image_height()),
          m_rows(grid.rows() - 1),
          m_columns(grid.columns() - 1),
          m_row_slots(static_cast<size_t>(m_rows) * (m_width + 1)),
          m_slots(new Slot[m_row_slots + static_cast<size_t>(m_columns) * (m_height + 1)]) {}

    // Whether corner (x, y) (0 ≤ x ≤ W, 0 ≤ y ≤ H) lies on a border between two tiles.
    bool shared(int x, int y) const { return row_line(y) >= 0 || column_line(x) >= 0; }

    // The value of the shared corner (x, y): `trace()` once per image, by the first caller; the
    // others wait for it while it is being traced.
    template <typename Trace>
    Sample get(int x, int y, Trace&& trace) {
        Slot& slot = this->slot(x, y);
        for (;;) {
            int state = slot.state.load(std::memory_order_acquire);
            if (state == kDone) return slot.value;
            if (state == kEmpty &&
                slot.state.compare_exchange_strong(state, kTracing, std::memory_order_acq_rel)) {
                try {
                    slot.value = trace();
                } catch (...) {
                    slot.state.store(kEmpty, std::memory_order_release);  // another may retry
                    throw;
                }
                slot.state.store(kDone, std::memory_order_release);
                return slot.value;
            }
            std::this_thread::yield();  // another tile is tracing it: one ray's wait
        }
    }

  private:
    static constexpr int kEmpty = 0, kTracing = 1, kDone = 2;
    struct Slot {
        std::atomic<int> state{kEmpty};
        Sample value{};
    };
    // The interior border line that y (x) lies on, 0-based, or -1.
    int row_line(int y) const {
        return y > 0 && y < m_height && y % m_tile == 0 ? y / m_tile - 1 : -1;
    }
    int column_line(int x) const {
        return x > 0 && x < m_width && x % m_tile == 0 ? x / m_tile - 1 : -1;
    }
    // A corner where a row line and a column line cross is kept on the row line.
    Slot& slot(int x, int y) {
        const int row = row_line(y);
        if (row >= 0) return m_slots[static_cast<size_t>(row) * (m_width + 1) + x];
        return m_slots[m_row_slots + static_cast<size_t>(column_line(x)) * (m_height + 1) + y];
    }

    int m_tile, m_width, m_height, m_rows, m_columns;
    size_t m_row_slots;
    std::unique_ptr<Slot[]> m_slots;
};

}  // namespace rayo
