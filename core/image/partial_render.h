#pragma once
// The finished tiles of an interrupted render, kept beside its output so that `rayo render
// --resume` renders only the missing ones (docs/high-resolution.md, "Interrupt and resume").
// One file, OUTPUT.rayo-partial: a text header with the render's fingerprint (the scene's
// contents and every setting that decides the pixels), then one fixed-size slot per tile of
// the grid, in tile order, each a record of the tile's float RGBA pixels (scene-linear, as the
// tile loop produced them) behind a small header with the tile index and a checksum. A record
// counts only when its checksum matches, so a record torn by `kill -9` or a power loss is
// rendered again; tiles are written by a thread of their own (pwrite as they come, fdatasync at
// most once a second and when flushed or closed), and a tile counts as done only once it is on
// the disk. A new partial render keeps the tiles finished from `keep_after` into the render on
// (`rayo render --journal-after`, 2 s by default): a render shorter than that writes no file,
// and an interrupted one loses at most that much work. Whatever the output format, resuming
// feeds the saved floats to the output's sink as if just rendered: the result is the same bits
// as an uninterrupted render.
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/tile_grid.h"
#include "core/tile_sink.h"

namespace rayo {

// What decides a render's pixels, as (name, value) pairs in a fixed order: "scene contents",
// "resolution", "spp", ... A resume must match it entry for entry.
using RenderFingerprint = std::vector<std::pair<std::string, std::string>>;

// OUTPUT.rayo-partial.
std::string partial_render_path(const std::string& output);

// A fingerprint as "name: value" lines (a value's line breaks become spaces), and back.
std::string fingerprint_text(const RenderFingerprint& fingerprint);
RenderFingerprint parse_fingerprint(const std::string& text);
// Every entry that differs between a fingerprint kept in a file (`kept` names the file's kind:
// "partial render") and the render's now, a line each ("\n  spp: 1 in the partial render, 2
// now"); empty when they match.
std::string fingerprint_differences(const RenderFingerprint& before, const RenderFingerprint& now,
                                    const std::string& kept);

// A 64-bit checksum of `bytes` bytes (a multiple of 8): FNV-1a over 64-bit words.
uint64_t checksum64(const void* data, size_t bytes);

class PartialRender {
  public:
    // A new partial render of `output` for `grid`; its file is created with the first tile
    // kept, the first to finish `keep_after` or later after this call (earlier ones are not
    // kept). InputError(output) when a partial render of it exists already (it is not
    // discarded: it is resumed with --resume, or removed by the user to start over).
    static std::unique_ptr<PartialRender> create(
        const std::string& output, const TileGrid& grid, const RenderFingerprint& fingerprint,
        std::chrono::steady_clock::duration keep_after = std::chrono::steady_clock::duration(0));
    // The partial render of `output`, its valid tiles found (checksums read). InputError(output)
    // when there is none, when it is not a partial render, or when its fingerprint differs from
    // `fingerprint` (every difference named: "spp: 1 in the partial render, 2 now").
    static std::unique_ptr<PartialRender> resume(const std::string& output, const TileGrid& grid,
                                                 const RenderFingerprint& fingerprint);
    // Waits for the tiles queued, then closes the file; removes it when it holds no tile.
    ~PartialRender();
    PartialRender(const PartialRender&) = delete;
    PartialRender& operator=(const PartialRender&) = delete;

    const std::string& path() const { return m_path; }
    int tile_count() const { return m_grid.tile_count(); }
    // Tiles on the disk (those of earlier runs included).
    int tiles_done() const;
    // The tiles not on the disk when the partial render was opened, in tile order.
    std::vector<int> missing_tiles() const;

    // A sink that passes every tile to `inner` and records it here; its begin() first feeds
    // `inner` the tiles saved by earlier runs (read back from the file), in tile order.
    std::unique_ptr<TileSink> recording_sink(TileSink& inner);

    // Whether the recording sink's finish() ran: every tile reached the output's sink (the tile
    // loop skips finish() when a stop request ended the hand-out early).
    bool complete() const { return m_complete; }

    // Waits until every recorded tile is on the disk (or the partial render failed).
    void flush();
    // Why the partial render stopped growing (a write failed: e.g. a full disk, it needs 16 bytes
    // a pixel), or empty. The render goes on without it; the tiles on the disk before the
    // failure stay resumable.
    std::string failure() const;
    // Removes the file (the output is complete).
    void remove();

    // For tests (RAYO_TEST_INTERRUPT, apps/cli): raise `signal_number` on the worker that
    // finishes the `tiles`-th tile of this run, as a user's Ctrl-C or kill would at that point
    // (with one thread and every tile kept, exactly `tiles` tiles are then done).
    void raise_after(int tiles, int signal_number);

  private:
    PartialRender(const std::string& output, const TileGrid& grid,
                  const RenderFingerprint& fingerprint);
    struct Job {
        Tile tile;
        std::vector<float> rgba;
    };
    class Recorder;

    void record(const Tile& tile, const float* rgba);
    void replay(TileSink& inner) const;
    void scan();
    void run();
    void write_batch(const std::deque<Job>& batch);
    void open_for_writing();
    size_t slot_bytes() const;
    size_t slot_offset(int index) const;
    [[noreturn]] void fail(const std::string& what, int error) const;

    std::string m_output, m_path;
    TileGrid m_grid;
    std::string m_header;  // the file's header, padded to m_header_bytes
    size_t m_header_bytes = 0;
    int m_fd = -1;
    bool m_existing = false;   // opened by resume()
    bool m_complete = false;   // the recording sink's finish() ran
    std::vector<char> m_done;  // per tile: on the disk
    int m_done_count = 0;
    int m_finished_this_run = 0;
    std::chrono::steady_clock::time_point m_keep_from;  // tiles finished earlier are not kept
    int m_raise_after = 0, m_raise_signal = 0;

    mutable std::mutex m_mutex;
    std::condition_variable m_wake, m_idle;
    std::deque<Job> m_jobs;
    size_t m_queued_bytes = 0;
    std::vector<int> m_unsynced;  // tiles written, waiting for the next fdatasync
    bool m_writing = false, m_stop = false, m_sync_requested = false;
    std::string m_error;
    std::thread m_thread;
};

}  // namespace rayo
