#include "apps/mpi/mpi_tile_distribution.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>
#include <iostream>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <thread>

#include "apps/mpi/mpi_world.h"

#if RAYO_HAVE_MPI
#include <mpi.h>
#endif

namespace rayo {
#if RAYO_HAVE_MPI
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Hands out the tiles to render in chunks, to any thread: about two tiles per render thread
// of the asking rank, fewer toward the end (a share of what is left per rank), so that the
// ranks finish together.
class TileQueue {
  public:
    TileQueue(std::vector<int> tiles, int processes)
        : m_tiles(std::move(tiles)), m_processes(processes) {}

    std::vector<int> take(int threads) {
        std::lock_guard<std::mutex> lock(m_mutex);
        const size_t remaining = m_tiles.size() - m_next;
        const size_t share = remaining / (2 * static_cast<size_t>(m_processes));
        const size_t n = std::min(remaining, std::clamp<size_t>(share, 1, 2 * size_t(threads)));
        std::vector<int> chunk(m_tiles.begin() + long(m_next), m_tiles.begin() + long(m_next + n));
        m_next += n;
        return chunk;
    }

  private:
    std::mutex m_mutex;
    std::vector<int> m_tiles;
    size_t m_next = 0;
    int m_processes;
};

// Passes tiles on to the image's sink and counts their pixels; the sink's begin() and
// finish() belong to the distribution, not to each chunk.
class ForwardingSink : public TileSink {
  public:
    ForwardingSink(TileSink& sink, ProgressReporter* progress)
        : m_sink(sink), m_progress(progress) {}
    void write_tile(const Tile& tile, const float* rgba) override {
        m_sink.write_tile(tile, rgba);
        if (m_progress) m_progress->add(tile.pixel_count());
    }

  private:
    TileSink& m_sink;
    ProgressReporter* m_progress;
};

std::vector<int> tile_list(const TileGrid& grid, const std::vector<int>& tiles) {
    if (!tiles.empty()) return tiles;
    std::vector<int> all(static_cast<size_t>(grid.tile_count()));
    std::iota(all.begin(), all.end(), 0);
    return all;
}

constexpr int kTag = 4242;
enum MessageKind : int32_t { kRequest = 1, kTile = 2, kDone = 3 };
// Every message to rank 0 starts with this; a tile's float RGBA or a ProcessWork follows.
struct Header {
    int32_t kind = 0;
    int32_t value = 0;  // kRequest: the rank's threads; kTile: the tile index
};

// A chunk's finished tiles, kept until they are sent.
class CollectingSink : public TileSink {
  public:
    struct Finished {
        Tile tile;
        std::vector<float> rgba;
    };
    void write_tile(const Tile& tile, const float* rgba) override {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_tiles.push_back({tile, std::vector<float>(rgba, rgba + tile.pixel_count() * 4)});
    }
    std::vector<Finished>& tiles() { return m_tiles; }

  private:
    std::mutex m_mutex;
    std::vector<Finished> m_tiles;
};

void send_to_rank_zero(const Header& header, const void* payload, size_t bytes,
                       std::vector<unsigned char>& buffer) {
    buffer.resize(sizeof(Header) + bytes);
    std::memcpy(buffer.data(), &header, sizeof(Header));
    if (bytes > 0) std::memcpy(buffer.data() + sizeof(Header), payload, bytes);
    MPI_Send(buffer.data(), static_cast<int>(buffer.size()), MPI_BYTE, 0, kTag, MPI_COMM_WORLD);
}

// An error where other ranks wait for this one: say it here and end them all.
[[noreturn]] void fail_everywhere(const char* what) {
    std::cerr << "rayo: error: rank " << MpiWorld::rank() << ": " << what << "\n";
    std::cerr.flush();
    MpiWorld::abort(1);
}

}  // namespace
#endif

MpiTileDistribution::MpiTileDistribution(int threads) : m_threads(std::max(1, threads)) {}

bool MpiTileDistribution::writes_image() const {
    return MpiWorld::rank() == 0;
}

int MpiTileDistribution::follow_writer(int decision) {
#if RAYO_HAVE_MPI
    if (MpiWorld::distributed()) MPI_Bcast(&decision, 1, MPI_INT, 0, MPI_COMM_WORLD);
#endif
    return decision;
}

RayCounters MpiTileDistribution::render(const TileGrid& grid, const std::vector<int>& tiles,
                                        const RenderTilesFunction& render_tiles, TileSink& sink,
                                        ProgressReporter* progress) {
#if RAYO_HAVE_MPI
    if (!MpiWorld::distributed()) {
        throw std::logic_error("MpiTileDistribution: a world of one renders without one");
    }
    m_work.assign(static_cast<size_t>(MpiWorld::size()), ProcessWork{});
    // Every rank has its scene and BVH: the ranks that failed before this point said so (and
    // one of them printed why); the others stop here too.
    const int failure = MpiWorld::agree_on_failure(false, {}, 0, std::cerr);
    if (failure != 0) throw PeerFailure(failure);
    m_agreed = true;
    try {
        if (MpiWorld::rank() == 0) return coordinate(grid, tiles, render_tiles, sink, progress);
        return work_for_rank_zero(render_tiles);
    } catch (const std::exception& e) {
        fail_everywhere(e.what());
    }
#else
    (void)grid, (void)tiles, (void)render_tiles, (void)sink, (void)progress;
    throw std::logic_error("MpiTileDistribution: rayo was built without MPI");
#endif
}

#if RAYO_HAVE_MPI
RayCounters MpiTileDistribution::coordinate(const TileGrid& grid, const std::vector<int>& tiles,
                                            const RenderTilesFunction& render_tiles, TileSink& sink,
                                            ProgressReporter* progress) {
    TileQueue queue(tile_list(grid, tiles), MpiWorld::size());
    sink.begin(grid);
    // Rank 0 renders too, on a second thread, so that only this (main) thread calls MPI.
    std::exception_ptr local_error;
    std::thread local([&] {
        try {
            const auto start = std::chrono::steady_clock::now();
            ForwardingSink forward(sink, progress);
            for (;;) {
                const std::vector<int> chunk = queue.take(m_threads);
                if (chunk.empty()) break;
                m_work[0].counters += render_tiles(chunk, forward);
                m_work[0].tiles += chunk.size();
            }
            m_work[0].seconds = seconds_since(start);
        } catch (...) {
            local_error = std::current_exception();
        }
    });
    int working = MpiWorld::size() - 1;
    std::vector<unsigned char> message;
    while (working > 0) {
        int arrived = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, kTag, MPI_COMM_WORLD, &arrived, &status);
        if (!arrived) {
            // Polling with a sleep: a blocking receive would spin and take a core from the
            // render threads.
            std::this_thread::sleep_for(std::chrono::microseconds(200));
            continue;
        }
        int bytes = 0;
        MPI_Get_count(&status, MPI_BYTE, &bytes);
        message.resize(static_cast<size_t>(bytes));
        MPI_Recv(message.data(), bytes, MPI_BYTE, status.MPI_SOURCE, kTag, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        Header header;
        std::memcpy(&header, message.data(), sizeof(Header));
        const unsigned char* payload = message.data() + sizeof(Header);
        const size_t payload_bytes = message.size() - sizeof(Header);
        if (header.kind == kRequest) {
            const std::vector<int> chunk = queue.take(header.value);
            MPI_Send(chunk.data(), static_cast<int>(chunk.size()), MPI_INT, status.MPI_SOURCE, kTag,
                     MPI_COMM_WORLD);
        } else if (header.kind == kTile) {
            const Tile tile = grid.tile(header.value);
            if (payload_bytes != tile.pixel_count() * 4 * sizeof(float)) {
                throw std::runtime_error("a tile from rank " + std::to_string(status.MPI_SOURCE) +
                                         " has the wrong size");
            }
            // The vector's storage is suitably aligned for float after the 8-byte header.
            sink.write_tile(tile, reinterpret_cast<const float*>(payload));
            if (progress) progress->add(tile.pixel_count());
        } else if (header.kind == kDone && payload_bytes == sizeof(ProcessWork)) {
            std::memcpy(&m_work[static_cast<size_t>(status.MPI_SOURCE)], payload,
                        sizeof(ProcessWork));
            --working;
        } else {
            throw std::runtime_error("an unknown message from rank " +
                                     std::to_string(status.MPI_SOURCE));
        }
    }
    local.join();
    if (local_error) std::rethrow_exception(local_error);
    sink.finish();
    RayCounters total;
    for (const ProcessWork& w : m_work) total += w.counters;
    return total;
}

RayCounters MpiTileDistribution::work_for_rank_zero(const RenderTilesFunction& render_tiles) {
    const auto start = std::chrono::steady_clock::now();
    ProcessWork& mine = m_work[static_cast<size_t>(MpiWorld::rank())];
    std::vector<unsigned char> message;
    for (;;) {
        send_to_rank_zero({kRequest, m_threads}, nullptr, 0, message);
        MPI_Status status;
        MPI_Probe(0, kTag, MPI_COMM_WORLD, &status);
        int count = 0;
        MPI_Get_count(&status, MPI_INT, &count);
        std::vector<int> chunk(static_cast<size_t>(count));
        MPI_Recv(chunk.data(), count, MPI_INT, 0, kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (chunk.empty()) break;
        CollectingSink collected;
        mine.counters += render_tiles(chunk, collected);
        for (const CollectingSink::Finished& f : collected.tiles()) {
            send_to_rank_zero({kTile, f.tile.index}, f.rgba.data(), f.rgba.size() * sizeof(float),
                              message);
            ++mine.tiles;
        }
    }
    mine.seconds = seconds_since(start);
    send_to_rank_zero({kDone, 0}, &mine, sizeof(ProcessWork), message);
    return mine.counters;
}
#endif

}  // namespace rayo
