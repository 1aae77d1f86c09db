#pragma once
// Where finished tiles go. The tile loop (core/render.h) hands every tile it renders to a sink
// once, from whichever worker thread finished it, in no particular order; sinks must accept
// concurrent calls for different tiles. The in-memory Film is the first sink (core/film.h). The
// interface is shaped for the sinks to come: a tiled EXR written as tiles finish (write_tile
// queues the tile for a writer thread; finish() waits for it and closes the file), a scanline
// PNG/TIFF writer (holds tiles until their band of rows is complete, then writes the band),
// and an MPI gather (write_tile sends the tile to rank 0, whose sink writes it).
#include "core/tile_grid.h"

namespace rayo {

class TileSink {
  public:
    virtual ~TileSink() = default;
    // Before the first tile: the grid the tiles come from.
    virtual void begin(const TileGrid& grid) { (void)grid; }
    // One finished tile: tile.width × tile.height pixels of float RGBA (scene-linear), row-major,
    // rows `tile.width` pixels apart. The data is valid only during the call.
    virtual void write_tile(const Tile& tile, const float* rgba) = 0;
    // After the last tile of this render; a sink that writes a file completes it here.
    virtual void finish() {}
};

}  // namespace rayo
