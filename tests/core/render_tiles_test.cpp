// The tile loop against stand-in cameras, integrators and sinks (no Embree): the grid covers the
// image once, every tile reaches the sink exactly once with its pixels, a tile list renders only
// those tiles, a camera may have no ray for a sample (alpha counts the samples that had one),
// and the lens sample reaches the camera; a failing tile stops the other workers.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/film.h"
#include "core/render.h"

namespace rayo {
namespace {

// Rays only for film x >= `first_column`; the ray's direction carries the film and lens samples.
struct HalfCamera {
    int w = 100, h = 70;
    float first_column = 50.0f;
    int width() const { return w; }
    int height() const { return h; }
    bool generate_ray(const glm::vec2& film, const glm::vec2& lens, Ray& ray) const {
        if (film.x < first_column) return false;
        ray.origin = Vec3(film.x, film.y, 0.0f);
        ray.direction = Vec3(lens.x, lens.y, 1.0f);
        return true;
    }
};

// Radiance = (x, y of the film position, lens u): what the camera was asked for.
struct EchoIntegrator {
    Vec3 radiance(const Ray& ray, const PixelSample& sample, RayCounters& counters) const {
        ++counters.camera;
        // The sample names the pixel whose film position the camera was given.
        EXPECT_EQ(static_cast<float>(sample.x), std::floor(ray.origin.x + 0.5f));
        EXPECT_EQ(static_cast<float>(sample.y), std::floor(ray.origin.y + 0.5f));
        return Vec3(ray.origin.x, ray.origin.y, ray.direction.x);
    }
    void radiance_coherent(const Ray* rays, const PixelSample* samples, int count, Vec3* out,
                           RayCounters& counters) const {
        for (int i = 0; i < count; ++i) out[i] = radiance(rays[i], samples[i], counters);
    }
};

struct RecordingSink : TileSink {
    std::mutex mutex;
    std::vector<Tile> tiles;
    int begun = 0, finished = 0;
    void begin(const TileGrid&) override { ++begun; }
    void write_tile(const Tile& tile, const float* rgba) override {
        const std::lock_guard<std::mutex> lock(mutex);
        tiles.push_back(tile);
        // The first pixel of the tile is the tile's top-left pixel.
        if (tile.x0 >= 50) {
            EXPECT_EQ(rgba[0], static_cast<float>(tile.x0));
        }
        EXPECT_EQ(rgba[1], tile.x0 >= 50 ? static_cast<float>(tile.y0) : 0.0f);
    }
    void finish() override { ++finished; }
};

TEST(TileGrid, CoversTheImageOnceWithEdgeTilesCut) {
    const TileGrid grid(100, 70, 32);
    EXPECT_EQ(grid.columns(), 4);
    EXPECT_EQ(grid.rows(), 3);
    size_t pixels = 0;
    for (int i = 0; i < grid.tile_count(); ++i) pixels += grid.tile(i).pixel_count();
    EXPECT_EQ(pixels, 100u * 70u);
    const Tile last = grid.tile(grid.tile_count() - 1);
    EXPECT_EQ(last.x0, 96);
    EXPECT_EQ(last.width, 4);
    EXPECT_EQ(last.height, 6);
    EXPECT_THROW(TileGrid(100, 70, 24), InputError);  // not a multiple of 16
    EXPECT_THROW(TileGrid(100, 70, 0), InputError);
}

TEST(RenderTiles, EveryTileReachesTheSinkOnce) {
    for (bool coherent : {false, true}) {
        RecordingSink sink;
        TileSettings settings;
        settings.tile_size = 16;
        settings.coherent = coherent;
        render_tiles(HalfCamera{}, EchoIntegrator{}, settings, sink);
        EXPECT_EQ(sink.begun, 1);
        EXPECT_EQ(sink.finished, 1);
        std::set<int> indices;
        for (const Tile& t : sink.tiles) indices.insert(t.index);
        EXPECT_EQ(sink.tiles.size(), 7u * 5u);
        EXPECT_EQ(indices.size(), 7u * 5u);
    }
}

TEST(RenderTiles, ATileListRendersOnlyThoseTiles) {
    RecordingSink sink;
    TileSettings settings;
    settings.tile_size = 32;
    render_tiles(HalfCamera{}, EchoIntegrator{}, settings, sink, nullptr, {5, 2});
    ASSERT_EQ(sink.tiles.size(), 2u);
    std::set<int> indices{sink.tiles[0].index, sink.tiles[1].index};
    EXPECT_EQ(indices, (std::set<int>{2, 5}));
}

TEST(RenderTiles, SamplesWithoutARayCountInAlphaOnly) {
    HalfCamera camera;
    camera.first_column = 49.0f;  // pixel 49's samples (x in [48.5, 49.5)) straddle the edge
    for (bool coherent : {false, true}) {
        Film film(camera.w, camera.h);
        TileSettings settings;
        settings.spp = 16;
        settings.coherent = coherent;
        const RayCounters counters = render_tiles(camera, EchoIntegrator{}, settings, film);
        EXPECT_EQ(film.rgb(10, 10), Vec3(0.0f));
        EXPECT_EQ(film.rgba()[(10 * 100 + 10) * 4 + 3], 0.0f);
        EXPECT_EQ(film.rgba()[(10 * 100 + 80) * 4 + 3], 1.0f);
        const float edge_alpha = film.rgba()[(10 * 100 + 49) * 4 + 3];
        EXPECT_GT(edge_alpha, 0.0f);
        EXPECT_LT(edge_alpha, 1.0f);
        // The film position's mean is the pixel centre's column; the lens samples are
        // stratified over [0, 1): their mean is near 1/2.
        EXPECT_NEAR(film.rgb(80, 10).x, 80.0f, 0.05f);
        EXPECT_NEAR(film.rgb(80, 10).z, 0.5f, 0.1f);
        EXPECT_GT(counters.camera, 50u * 70u * 16u);
        EXPECT_LT(counters.camera, 51u * 70u * 16u);
    }
}

TEST(RenderTiles, OneSamplePerPixelLooksThroughThePixelAndLensCentres) {
    Film film(100, 70);
    TileSettings settings;
    render_tiles(HalfCamera{}, EchoIntegrator{}, settings, film);
    EXPECT_EQ(film.rgb(60, 33), Vec3(60.0f, 33.0f, 0.5f));
}

// A tile that fails (here the sink, as a full disk would) ends the render: its exception reaches
// the caller, the other workers stop taking tiles (before, they rendered the rest of the image
// for nothing), and finish() is not called. The sink makes the schedule deterministic: the first
// tile's write waits until a second worker is writing too, and that worker waits until the
// first has thrown; what the second worker writes after that is counted, each write taking
// 5 ms as a real tile would.
TEST(RenderTiles, AFailingTileStopsTheOtherWorkers) {
    struct FailingSink : TileSink {
        std::mutex mutex;
        std::condition_variable changed;
        int writes = 0, writes_after_failure = 0, finished = 0;
        bool second_worker_writing = false, thrown = false;
        void write_tile(const Tile&, const float*) override {
            std::unique_lock<std::mutex> lock(mutex);
            if (thrown) {
                // A tile takes milliseconds in a real render; the thrower's unwinding to the
                // loop's catch (slow the first time in a process) must not look like a miss.
                ++writes_after_failure;
                lock.unlock();
                std::this_thread::sleep_for(std::chrono::milliseconds(5));
                return;
            }
            if (++writes == 1) {
                const bool met = changed.wait_for(lock, std::chrono::seconds(20),
                                                  [&] { return second_worker_writing; });
                EXPECT_TRUE(met) << "no second worker came to write a tile";
                thrown = true;
                changed.notify_all();
                throw std::runtime_error("disk full");
            }
            second_worker_writing = true;
            changed.notify_all();
            changed.wait(lock, [&] { return thrown; });
        }
        void finish() override { ++finished; }
    } sink;
    TileSettings settings;
    settings.tile_size = 16;
    const HalfCamera camera{256, 256, 0.0f};  // 256 tiles
    // Two threads even on a one-core machine.
    tbb::global_control two_threads(tbb::global_control::max_allowed_parallelism, 2);
    tbb::task_arena two_workers(2);
    two_workers.execute([&] {
        EXPECT_THROW(render_tiles(camera, EchoIntegrator{}, settings, sink), std::runtime_error);
    });
    // The second worker may take a few tiles before the failure is flagged, not the other 254.
    EXPECT_LE(sink.writes_after_failure, 20);
    EXPECT_EQ(sink.finished, 0);
}

}  // namespace
}  // namespace rayo
