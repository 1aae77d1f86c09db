#pragma once
// Who renders which tiles of the grid (core/tile_grid.h). One process renders them all through
// the tile loop (core/render.h); a distribution shares them out among processes (MPI ranks:
// apps/mpi/mpi_tile_distribution.h) and brings every finished tile to the one process that
// writes the image. The pixels do not depend on which process renders a tile (samples come
// from the stateless hash of the pixel, core/sampling.h), so the image is the same bits for any
// number of processes.
#include <cstdint>
#include <functional>
#include <vector>

#include "core/progress.h"
#include "core/stats.h"
#include "core/tile_grid.h"
#include "core/tile_sink.h"

namespace rayo {

// Renders the listed tiles into a sink: the tile loop bound to a camera and an integrator. It
// calls the sink's begin() and finish() itself.
using RenderTilesFunction = std::function<RayCounters(const std::vector<int>& tiles, TileSink&)>;

// What one process did, for the summary.
struct ProcessWork {
    uint64_t tiles = 0;
    RayCounters counters;
    double seconds = 0.0;  // from its first tile request to its last tile sent
};

class TileDistribution {
  public:
    virtual ~TileDistribution() = default;
    // Renders `tiles` of `grid` (every tile when empty) among the processes. On the process
    // that writes the image every tile reaches `sink` once, between one begin() and one
    // finish(), and `progress` (if any) counts its pixels; other processes' `sink` gets nothing.
    // Returns the ray counts of all processes on the writing process, its own elsewhere.
    virtual RayCounters render(const TileGrid& grid, const std::vector<int>& tiles,
                               const RenderTilesFunction& render_tiles, TileSink& sink,
                               ProgressReporter* progress) = 0;
    // Whether this process writes the image (gets the tiles, prints the summary).
    virtual bool writes_image() const = 0;
    // Per process (index = rank), filled on the writing process by render().
    virtual const std::vector<ProcessWork>& work() const = 0;
    // Collective: every process returns the `decision` the writing process passed (what a loop
    // of renders does next, decided where the image is: core/progressive.h's passes).
    virtual int follow_writer(int decision) = 0;
};

}  // namespace rayo
