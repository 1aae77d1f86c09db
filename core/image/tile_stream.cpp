#include "core/image/tile_stream.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "core/error.h"
#include "core/image/atomic_file.h"
#include "core/image/image_writers.h"
#include "core/image/interrupt_cleanup.h"
#include "core/image/output_encoding.h"
#include "core/image_library.h"

namespace rayo {

namespace {

// The most bytes queued for the writer thread before workers wait (at least one item is always
// taken), besides the batch the writer took and is writing. What is queued or being written when
// the last tile finishes is what finish() still has to write: at 16 MB, 256 EXR tiles took 0.3 s
// to compress after a 2 s render at 2048²; at 2 MB, 32 tiles.
constexpr size_t kStreamQueueBytes = size_t(2) << 20;

std::string size_text(long long width, long long height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

// The temporary file of one output, its writer (the image module's) and the writer thread. Pieces
// pushed are queued; the writer thread takes everything queued at once and hands the batch, in the
// order pushed, to `write` (the EXR stream joins adjacent tiles of a batch into one write_tiles
// call, which OpenEXR compresses on its thread pool). `write` returns false on failure; the first
// failure is kept and reported by push() and finish(). Destroyed without a successful finish(),
// it stops the thread and removes the temporary.
template <typename Piece>
class FileWriter {
  public:
    using WriteBatch = std::function<bool(ImageWriter&, std::vector<Piece>&)>;

    // The temporary file is created here, so that an unwritable output fails before the render;
    // the image module's writer is opened on the writer thread, so that the render does not wait
    // for the module to load (docs/performance.md "Fixed costs"): tiles queue meanwhile.
    FileWriter(const std::string& path, const ImageFileSpec& spec, ImageWriterChoice choice,
               WriteBatch write)
        : m_path(path),
          m_tmp(temporary_path_for(path)),
          m_guard(m_tmp),
          m_choice(choice),
          m_write(std::move(write)) {
        errno = 0;
        if (std::FILE* file = std::fopen(m_tmp.c_str(), "wb")) {
            std::fclose(file);
        } else {
            fail_now("cannot create the temporary file");
        }
        m_thread = std::thread([this, spec] { run(spec); });
    }

    ~FileWriter() {
        if (m_thread.joinable()) {
            {
                std::lock_guard<std::mutex> lock(m_mutex);
                m_stop = true;
                m_abandon = true;
            }
            m_wake.notify_all();
            m_thread.join();
        }
        if (!m_committed) {
            m_out.reset();  // closes the file
            std::remove(m_tmp.c_str());
        }
    }

    // Queues a piece of `bytes` held bytes; waits while the queue holds kStreamQueueBytes (unless
    // it is empty). Throws the writer's failure, if any.
    void push(size_t bytes, Piece piece) {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_room.wait(lock, [&] {
            return !m_error.empty() || !m_open || m_pieces.empty() ||
                   m_queued + bytes <= kStreamQueueBytes;
        });
        throw_failure(lock);
        m_queued += bytes;
        m_pieces.push_back(std::move(piece));
        m_wake.notify_one();
    }

    // Writes what is queued, closes the file and renames it onto the path.
    void finish() {
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_stop = true;
        }
        m_wake.notify_all();
        m_thread.join();
        {
            std::unique_lock<std::mutex> lock(m_mutex);
            throw_failure(lock);
        }
        errno = 0;
        if (!m_out->close()) fail_now(m_out->error());
        if (std::rename(m_tmp.c_str(), m_path.c_str()) != 0)
            fail_now("cannot rename the temporary file");
        m_committed = true;
    }

  private:
    // Opens the writer, then takes the whole queue at once: the queue has room again while the
    // batch is written (at most two queues' worth of pieces are held), and the batch is as large
    // as the writer fell behind. Until the writer is open the queue is not bounded: the tiles of
    // the module's load time (a fraction of a second of rendering) wait in memory.
    void run(const ImageFileSpec& spec) {
        open_writer(spec);
        std::unique_lock<std::mutex> lock(m_mutex);
        std::vector<Piece> batch;
        for (;;) {
            m_wake.wait(lock, [&] { return m_stop || !m_pieces.empty(); });
            if (m_abandon || (m_pieces.empty() && m_stop)) return;
            batch.assign(std::make_move_iterator(m_pieces.begin()),
                         std::make_move_iterator(m_pieces.end()));
            m_pieces.clear();
            m_queued = 0;
            m_room.notify_all();
            if (!m_error.empty()) continue;
            lock.unlock();
            errno = 0;
            const bool ok = m_write(*m_out, batch);
            const int error = errno;
            const std::string reason = ok ? std::string() : m_out->error();
            batch.clear();
            lock.lock();
            if (!ok) {
                m_error = write_failure(reason, error, m_tmp, m_path);
                m_room.notify_all();
            }
        }
    }

    // The writer on the temporary file (core/image/image_writers.h: libpng's or OpenEXR's, or the
    // image module's, loaded here when needed); a failure is kept for push() and finish().
    void open_writer(const ImageFileSpec& spec) {
        std::string failure;
        try {
            errno = 0;
            std::string reason;
            m_out = create_image_writer(m_tmp, spec, m_choice, reason);
            if (!m_out) failure = write_failure(reason, errno, m_tmp, m_path);
        } catch (const std::exception& e) {
            failure = e.what();
        }
        std::lock_guard<std::mutex> lock(m_mutex);
        m_open = true;
        if (!failure.empty()) m_error = failure;
        m_room.notify_all();
    }

    void throw_failure(std::unique_lock<std::mutex>&) const {
        if (!m_error.empty()) throw InputError(m_path, "cannot write: " + m_error);
    }
    [[noreturn]] void fail_now(const std::string& reason) const {
        throw InputError(m_path, "cannot write: " + write_failure(reason, errno, m_tmp, m_path));
    }

    std::string m_path, m_tmp;
    TemporaryFileGuard m_guard;
    ImageWriterChoice m_choice;
    WriteBatch m_write;
    std::unique_ptr<ImageWriter> m_out;
    std::mutex m_mutex;
    std::condition_variable m_wake, m_room;
    std::deque<Piece> m_pieces;
    size_t m_queued = 0;
    bool m_open = false, m_stop = false, m_abandon = false, m_committed = false;
    std::string m_error;
    std::thread m_thread;
};

// Seconds since `start`.
double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One finished tile's pixels, queued for the EXR writer.
struct TilePixels {
    Tile tile;
    std::vector<float> rgba;
};

// Writes a batch of tiles, each run of horizontally adjacent tiles (in the same tile row) as one
// write_tiles call: OpenEXR compresses the tiles of one call in parallel on its thread pool
// (OpenImageIO's "exr_threads", all cores by default), so compression is not bound to the one
// writer thread. `run` is the reused buffer a run is gathered into.
bool write_tile_runs(ImageWriter& out, std::vector<TilePixels>& tiles, std::vector<float>& run) {
    std::sort(tiles.begin(), tiles.end(), [](const TilePixels& a, const TilePixels& b) {
        return a.tile.y0 != b.tile.y0 ? a.tile.y0 < b.tile.y0 : a.tile.x0 < b.tile.x0;
    });
    for (size_t first = 0, last; first < tiles.size(); first = last) {
        const Tile& start = tiles[first].tile;
        int x1 = start.x0 + start.width;
        for (last = first + 1;
             last < tiles.size() && tiles[last].tile.y0 == start.y0 && tiles[last].tile.x0 == x1;
             ++last) {
            x1 += tiles[last].tile.width;
        }
        const float* pixels = tiles[first].rgba.data();
        if (last - first > 1) {
            const size_t run_width = x1 - start.x0;
            run.resize(run_width * start.height * 4);
            for (size_t t = first; t < last; ++t) {
                const Tile& tile = tiles[t].tile;
                for (int y = 0; y < tile.height; ++y) {
                    std::memcpy(&run[(y * run_width + (tile.x0 - start.x0)) * 4],
                                &tiles[t].rgba[static_cast<size_t>(y) * tile.width * 4],
                                tile.width * 4 * sizeof(float));
                }
            }
            pixels = run.data();
        }
        if (!out.write_tiles(start.x0, x1, start.y0, start.y0 + start.height, pixels)) {
            return false;
        }
    }
    return true;
}

// A tiled EXR: each tile is copied and queued as it arrives.
class ExrTileStream : public TileStream {
  public:
    ExrTileStream(const std::string& path, const ImageFileSpec& spec, ImageWriterChoice choice)
        : m_writer(path, spec, choice, [this](ImageWriter& out, std::vector<TilePixels>& tiles) {
              return write_tile_runs(out, tiles, m_run);
          }) {}

    void write_tile(const Tile& tile, const float* rgba) override {
        TilePixels piece{tile, std::vector<float>(rgba, rgba + tile.pixel_count() * 4)};
        const size_t bytes = piece.rgba.size() * sizeof(float);
        m_writer.push(bytes, std::move(piece));
    }

    void finish() override {
        const auto start = std::chrono::steady_clock::now();
        m_writer.finish();
        m_finish_seconds = seconds_since(start);
    }

  private:
    std::vector<float> m_run;  // the writer thread's buffer (write_tile_runs)
    FileWriter<TilePixels> m_writer;
};

// PNG/TIFF/JPEG: tiles encoded for display on the workers, gathered into bands of tile rows,
// complete bands written in order.
class BandStream : public TileStream {
  public:
    BandStream(const std::string& path, ImageFormat format, const ImageFileSpec& spec,
               const OutputOptions& options)
        : m_encoder(format, path, options),
          m_path(path),
          m_writer(path, spec, options.writer,
                   [type = m_encoder.type()](ImageWriter& out, std::vector<Band>& bands) {
                       for (const Band& band : bands) {
                           if (!out.write_scanlines(band.y0, band.y0 + band.height, type,
                                                    band.bytes.data()))
                               return false;
                       }
                       return true;
                   }) {}

    void begin(const TileGrid& grid) override { m_grid.emplace(grid); }

    void write_tile(const Tile& tile, const float* rgba) override {
        const size_t pixels = tile.pixel_count();
        const size_t pixel_bytes = m_encoder.bytes_per_pixel();
        std::vector<float> display(rgba, rgba + pixels * 4);
        DisplayEncoder::unpremultiply(display.data(), pixels);
        m_encoder.apply_view(display.data(), tile.width, tile.height);
        std::vector<unsigned char> encoded(pixels * pixel_bytes);
        m_encoder.quantise(display.data(), pixels, encoded.data());

        const TileGrid& grid = *m_grid;
        const int row = tile.y0 / grid.tile_size();
        const size_t row_bytes = static_cast<size_t>(grid.image_width()) * pixel_bytes;
        std::lock_guard<std::mutex> lock(m_mutex);
        Band& band = m_bands[row];
        if (band.bytes.empty()) {
            band.y0 = tile.y0;
            band.height = tile.height;
            band.missing = grid.columns();
            band.bytes.resize(row_bytes * tile.height);
        }
        for (int y = 0; y < tile.height; ++y) {
            std::memcpy(&band.bytes[y * row_bytes + tile.x0 * pixel_bytes],
                        &encoded[static_cast<size_t>(y) * tile.width * pixel_bytes],
                        tile.width * pixel_bytes);
        }
        --band.missing;
        // Bands go to the writer in file order, each once it and all above it are complete.
        for (auto next = m_bands.find(m_next_row);
             next != m_bands.end() && next->second.missing == 0; next = m_bands.find(m_next_row)) {
            Band band = std::move(next->second);
            m_bands.erase(next);
            ++m_next_row;
            const size_t bytes = band.bytes.size();
            m_writer.push(bytes, std::move(band));
        }
    }

    void finish() override {
        const auto start = std::chrono::steady_clock::now();
        if (!m_grid || m_next_row != m_grid->rows())
            throw InputError(m_path, "cannot write: the render did not deliver every tile");
        m_writer.finish();
        m_finish_seconds = seconds_since(start);
    }

  private:
    struct Band {
        int y0 = 0, height = 0, missing = 0;
        std::vector<unsigned char> bytes;
    };

    DisplayEncoder m_encoder;
    std::string m_path;
    std::optional<TileGrid> m_grid;
    std::mutex m_mutex;
    std::map<int, Band> m_bands;  // bands not yet queued, by tile row
    int m_next_row = 0;           // the next band to queue
    FileWriter<Band> m_writer;
};

}  // namespace

bool choose_streaming(const std::string& path, int width, int height, const OutputOptions& options,
                      StreamMode mode) {
    const ImageFormat format = image_format_of(path);
    const int side = max_image_side(format);
    if (width > side || height > side) {
        throw InputError(path, "cannot write " + size_text(width, height) +
                                   ": the format stores at most " + std::to_string(side) +
                                   " pixels a side");
    }
    const long long pixels = static_cast<long long>(width) * height;
    const bool normalize = format != ImageFormat::Exr && options.range == RangeMode::Normalize;
    if (normalize && mode == StreamMode::Always) {
        throw InputError(path,
                         "--range normalize needs the whole image's maximum before the "
                         "first row is written, so it cannot stream; use --range clamp, or "
                         "write EXR and normalize it afterwards");
    }
    const bool stream = mode == StreamMode::Always ||
                        (mode == StreamMode::Auto && !normalize && pixels > kStreamAbovePixels);
    if (!stream && pixels > kMaxFilmPixels) {
        throw InputError(path, "an image of " + size_text(width, height) + " (" +
                                   std::to_string(pixels) +
                                   " pixels) is too large for an "
                                   "in-memory film (at most " +
                                   std::to_string(kMaxFilmPixels) + " pixels, 4 GiB)" +
                                   (normalize ? ", which --range normalize needs; use --range "
                                                "clamp, or write EXR and normalize it afterwards"
                                              : "; let it stream (without --no-stream)"));
    }
    return stream;
}

std::unique_ptr<TileStream> TileStream::open(const std::string& path, int width, int height,
                                             int tile_size, const OutputOptions& options) {
    const ImageFormat format = image_format_of(path);
    ImageFileSpec spec = image_spec(format, width, height, options);
    if (format == ImageFormat::Exr) {
        spec.tile_size = tile_size;
        // Tiles are written as they finish: OpenEXR must not buffer out-of-order tiles.
        spec.add("openexr:lineOrder", "randomY");
        return std::make_unique<ExrTileStream>(path, spec, options.writer);
    }
    return std::make_unique<BandStream>(path, format, spec, options);
}

}  // namespace rayo
