#pragma once
// Image files written while the render runs, in memory that does not grow with the image
// (docs/high-resolution.md). Each is a tile sink (core/tile_sink.h):
// - EXR: a tiled OpenEXR file (tiles of the render's tile size, line order "random Y"), every
//   finished tile queued to a writer thread as it arrives, in any order: writing overlaps
//   rendering, and finish() only writes what is still queued. The writer takes the whole queue
//   at once and writes each run of horizontally adjacent tiles in one write_tiles call, which
//   OpenEXR compresses on its thread pool: compression is not held to one thread.
// - PNG/TIFF/JPEG: each tile goes through the display encoding on the worker that rendered it
//   (core/image/output_encoding.h: the OCIO view is per pixel) into the band of tile rows it
//   belongs to; a band is queued to the writer thread, which writes scanlines in order, once it
//   and every band above it are complete. Only bands not yet written are held.
// The writer's queue is bounded (2 MB, plus the batch being written): workers wait when the disk
// or the compressor falls behind, and what is left to write after the last tile stays small.
// Files are written to a temporary name and renamed by finish(), as write_image does; a stream
// destroyed without a successful finish() removes its temporary. The pixels are those of
// write_image on the same film, bit for bit (tests/image/tile_stream_test.cpp).
#include <cstddef>
#include <memory>
#include <string>

#include "core/image/image_output.h"
#include "core/tile_sink.h"

namespace rayo {

enum class StreamMode {
    Auto,    // stream images of more than kStreamAbovePixels pixels
    Always,  // --stream
    Never,   // --no-stream: the in-memory film
};

// Above this many pixels (1024 × 1024, a 16 MiB film) Auto streams.
constexpr long long kStreamAbovePixels = 1LL << 20;

// Whether `path` (width × height) is streamed under `mode`. InputError(path) with the reason when
// neither way works: a side beyond what the format stores, --range normalize with streaming of
// a display format, or an in-memory film of more than kMaxFilmPixels pixels (core/film.h; the
// limit of --no-stream and of --range normalize for display formats).
bool choose_streaming(const std::string& path, int width, int height, const OutputOptions& options,
                      StreamMode mode);

class TileStream : public TileSink {
  public:
    // Opens the temporary file of `path` (format from the extension) for tiles of `tile_size`.
    // InputError(path) when it cannot be created or the display/view is unknown.
    static std::unique_ptr<TileStream> open(const std::string& path, int width, int height,
                                            int tile_size, const OutputOptions& options);
    ~TileStream() override = default;

    // The seconds finish() took: what writing adds after the last tile.
    double finish_seconds() const { return m_finish_seconds; }

  protected:
    double m_finish_seconds = 0.0;
};

}  // namespace rayo
