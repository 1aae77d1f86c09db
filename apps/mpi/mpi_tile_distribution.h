#pragma once
// Tiles shared out among MPI ranks (docs/distributed.md): rank 0 hands out tile indices on
// request, in chunks that shrink toward the end (guided scheduling), renders chunks itself on a
// second thread, and receives every finished tile into the sink; no other rank holds more than
// the tiles of its current chunk. Only for a world of several ranks (MpiWorld::distributed());
// one process renders without a distribution.
#include <exception>
#include <vector>

#include "core/tile_distribution.h"

namespace rayo {

// Thrown on the ranks that did not fail when another rank failed before the render (its
// message printed there, once): the rank exits with `exit_code`, printing nothing.
struct PeerFailure : std::exception {
    explicit PeerFailure(int code) : exit_code(code) {}
    const char* what() const noexcept override { return "another rank failed"; }
    int exit_code;
};

class MpiTileDistribution : public TileDistribution {
  public:
    // `threads`: this rank's render threads, which sizes the chunks it asks for.
    explicit MpiTileDistribution(int threads);

    RayCounters render(const TileGrid& grid, const std::vector<int>& tiles,
                       const RenderTilesFunction& render_tiles, TileSink& sink,
                       ProgressReporter* progress) override;
    bool writes_image() const override;
    int follow_writer(int decision) override;
    const std::vector<ProcessWork>& work() const override { return m_work; }
    // Whether render() has passed the ranks' agreement that none failed before it: an error
    // before that point must be agreed on (MpiWorld::agree_on_failure); an error after it ends
    // every rank (MpiWorld::abort).
    bool agreed() const { return m_agreed; }

  private:
    RayCounters coordinate(const TileGrid& grid, const std::vector<int>& tiles,
                           const RenderTilesFunction& render_tiles, TileSink& sink,
                           ProgressReporter* progress);
    RayCounters work_for_rank_zero(const RenderTilesFunction& render_tiles);

    int m_threads;
    bool m_agreed = false;
    std::vector<ProcessWork> m_work;
};

}  // namespace rayo
