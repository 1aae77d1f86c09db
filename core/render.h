#pragma once
// The tile-parallel render loop: the image's fixed tile grid (core/tile_grid.h), tiles in
// tbb::parallel_for, stratified samples per pixel from the stateless hash (core/sampling.h),
// per-thread ray counters merged at the end, every finished tile handed to a sink
// (core/tile_sink.h). Generic over the camera and the integrator, so the hot path has no
// virtual call:
//   camera:     int width() const; int height() const;
//               bool generate_ray(glm::vec2 film, glm::vec2 lens, Ray& out) const;
//   integrator: Vec3 radiance(const Ray&, const PixelSample&, RayCounters&) const;
//               void radiance_coherent(const Ray*, const PixelSample*, int, Vec3*,
//                                      RayCounters&) const;
// Each camera ray comes with its PixelSample (core/sampler.h): the pixel, the sample index and
// the stateless sampler the integrator draws its own dimensions from.
// The result does not depend on thread count, tile size or the coherent path: every pixel's
// samples are summed in a fixed order by the one task that owns the pixel, and the coherent
// path computes the same values as the single-ray one. Adaptive antialiasing
// (core/adaptive_aa.h) replaces the per-pixel samples tile by tile; "corners" is its corners
// alone, those on tile borders traced once for the image (core/tile_border_corners.h).
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <vector>

#include "core/adaptive_aa.h"
#include "core/math.h"
#include "core/progress.h"
#include "core/ray.h"
#include "core/sampler.h"
#include "core/sampling.h"
#include "core/stats.h"
#include "core/stop_request.h"
#include "core/tile_grid.h"
#include "core/tile_sink.h"
#include "core/tsan_handoff.h"

namespace rayo {

struct TileSettings {
    int spp = 1;
    int tile_size = kDefaultTileSize;
    // Camera rays of a tile in batches through the integrator's coherent path (Embree streams);
    // false: one ray at a time (the reference the coherent path is tested against).
    bool coherent = true;
    // Stratified: spp samples per pixel. Adaptive: corner subdivision, spp unused. Corners: the
    // mean of the four corners, each traced once (adaptive's corners without subdivision).
    AntiAliasing aa = AntiAliasing::Stratified;
    AdaptiveSettings adaptive;
    // The index of the first sample of each pixel: 0, or a progressive render's pass times its
    // spp (core/progressive.h). The pass's samples are stratified among themselves.
    uint32_t first_sample = 0;
};

// Camera ray for sample `s` of spp samples of pixel (x, y), whose index in the render is
// first_sample + s: stratified jitter on the film (the pixel centre when spp = 1) and on the
// lens. False where the camera has no ray (e.g. outside a fisheye's circle).
template <typename Camera>
bool pixel_ray(const Camera& camera, int x, int y, uint32_t s, uint32_t spp, Ray& ray,
               PixelSample& sample, uint32_t first_sample = 0) {
    const auto ux = static_cast<uint32_t>(x), uy = static_cast<uint32_t>(y);
    sample = PixelSample{ux, uy, first_sample + s, spp};
    const PixelOffset o = stratified_offset(ux, uy, s, spp, 0, first_sample);
    const glm::vec2 film(static_cast<float>(x) + o.dx, static_cast<float>(y) + o.dy);
    return camera.generate_ray(film, lens_sample(ux, uy, s, spp, first_sample), ray);
}

// One tile's pixels into `rgba` (tile-local, row-major).
template <typename Camera, typename Integrator>
void render_tile(const Camera& camera, const Integrator& integrator, bool coherent, uint32_t spp,
                 float inverse_spp, const Tile& tile, float* rgba, RayCounters& counters,
                 uint32_t first_sample = 0) {
    const int pixels = static_cast<int>(tile.pixel_count());
    auto store = [&](int i, const Vec3& sum, uint32_t rays) {
        float* p = rgba + static_cast<size_t>(i) * 4;
        const Vec3 mean = sum * inverse_spp;
        p[0] = mean.x;
        p[1] = mean.y;
        p[2] = mean.z;
        p[3] = rays == spp ? 1.0f : static_cast<float>(rays) * inverse_spp;
    };
    if (!coherent) {
        for (int i = 0; i < pixels; ++i) {
            const int x = tile.x0 + i % tile.width, y = tile.y0 + i / tile.width;
            Vec3 sum(0.0f);
            uint32_t rays = 0;
            for (uint32_t s = 0; s < spp; ++s) {
                Ray ray;
                PixelSample sample;
                if (!pixel_ray(camera, x, y, s, spp, ray, sample, first_sample)) continue;
                sum += integrator.radiance(ray, sample, counters);
                ++rays;
            }
            store(i, sum, rays);
        }
        return;
    }
    // Coherent batches: the tile in kCoherentBlock² blocks of the image's global block grid
    // (tile sizes are multiples of it), each block's pixels in row-major chunks of kChunk, one
    // batch per chunk and sample index. Embree's packet kernels can round triangle hits
    // differently from single rays, so the batches must not depend on the tile size: with the
    // global blocks they are the same for every tile size. Sums run over samples in the same
    // order as above.
    constexpr int kChunk = 64;
    Ray rays[kChunk];
    PixelSample samples[kChunk];
    Vec3 radiance[kChunk], sum[kChunk];
    int owner[kChunk];
    uint32_t ray_count[kChunk];
    for (int by = 0; by < tile.height; by += kCoherentBlock) {
        for (int bx = 0; bx < tile.width; bx += kCoherentBlock) {
            const int block_width = std::min(kCoherentBlock, tile.width - bx);
            const int block_pixels = block_width * std::min(kCoherentBlock, tile.height - by);
            for (int first = 0; first < block_pixels; first += kChunk) {
                const int n = std::min(kChunk, block_pixels - first);
                for (int i = 0; i < n; ++i) {
                    sum[i] = Vec3(0.0f);
                    ray_count[i] = 0;
                }
                for (uint32_t s = 0; s < spp; ++s) {
                    int batch = 0;
                    for (int i = 0; i < n; ++i) {
                        const int x = tile.x0 + bx + (first + i) % block_width;
                        const int y = tile.y0 + by + (first + i) / block_width;
                        if (!pixel_ray(camera, x, y, s, spp, rays[batch], samples[batch],
                                       first_sample)) {
                            continue;
                        }
                        owner[batch++] = i;
                    }
                    integrator.radiance_coherent(rays, samples, batch, radiance, counters);
                    for (int k = 0; k < batch; ++k) {
                        sum[owner[k]] += radiance[k];
                        ++ray_count[owner[k]];
                    }
                }
                for (int i = 0; i < n; ++i) {
                    const int local_x = bx + (first + i) % block_width;
                    const int local_y = by + (first + i) / block_width;
                    store(local_y * tile.width + local_x, sum[i], ray_count[i]);
                }
            }
        }
    }
}

// Renders the tiles of `grid` listed in `tiles` (all of them when empty) into `sink`. A pixel's
// alpha is the share of its samples that had a camera ray; samples without one add no radiance.
// A stop request (core/stop_request.h) ends the hand-out: the tiles in flight still reach the
// sink, and the sink's finish() is called only when every listed tile was delivered.
template <typename Camera, typename Integrator>
RayCounters render_tiles(const Camera& camera, const Integrator& integrator,
                         const TileSettings& settings, TileSink& sink,
                         ProgressReporter* progress = nullptr, const std::vector<int>& tiles = {}) {
    const TileGrid grid(camera.width(), camera.height(), settings.tile_size);
    const auto spp = static_cast<uint32_t>(settings.spp > 0 ? settings.spp : 1);
    const float inverse_spp = 1.0f / static_cast<float>(spp);
    const int count = tiles.empty() ? grid.tile_count() : static_cast<int>(tiles.size());
    tbb::enumerable_thread_specific<RayCounters> counters;
    tbb::enumerable_thread_specific<std::vector<float>> buffers;
    sink.begin(grid);

    // Tiles are handed out in order from one counter, one task per worker: a streaming sink
    // that writes rows in order (core/image/tile_stream.h) then holds only the few bands that
    // tiles in flight belong to. (A parallel_for over the tiles would split the range, and the
    // second worker would start in the middle of the image.)
    std::atomic<int> next_item{0};
    std::atomic<int> delivered{0};
    // Set by a worker whose tile failed (an exception from the integrator or the sink, e.g. a
    // full disk): the others stop taking tiles, and tbb rethrows the first exception here.
    std::atomic<bool> failed{false};
    const int workers = std::max(1, std::min(count, tbb::this_task_arena::max_concurrency()));
    // aa "corners": the corners on tile borders, traced by the first tile that needs them.
    std::unique_ptr<TileBorderCorners<CornerSample>> borders;
    AdaptiveSettings adaptive = settings.adaptive;
    if (settings.aa == AntiAliasing::Corners) {
        borders = std::make_unique<TileBorderCorners<CornerSample>>(grid);
        adaptive.depth = 0;
    }
    // The caller's writes (sink, counters) before every task; every task before the merge.
    int handoff = 0;
    tsan_release(&handoff);
    tbb::parallel_for(
        tbb::blocked_range<int>(0, workers, 1),
        [&](const tbb::blocked_range<int>&) {
            tsan_acquire(&handoff);
            RayCounters& local = counters.local();
            std::vector<float>& rgba = buffers.local();
            auto more = [&](int item) { return item < count && !failed && !stop_requested(); };
            try {
                for (int item = next_item.fetch_add(1); more(item); item = next_item.fetch_add(1)) {
                    const Tile tile = grid.tile(tiles.empty() ? item : tiles[item]);
                    rgba.assign(tile.pixel_count() * 4, 0.0f);
                    if (settings.aa != AntiAliasing::Stratified) {
                        AdaptiveTile<Camera, Integrator>(camera, integrator, adaptive, local,
                                                         borders.get())
                            .render(tile, rgba.data());
                    } else {
                        render_tile(camera, integrator, settings.coherent, spp, inverse_spp, tile,
                                    rgba.data(), local, settings.first_sample);
                    }
                    sink.write_tile(tile, rgba.data());
                    if (progress) progress->add(tile.pixel_count());
                    delivered.fetch_add(1, std::memory_order_relaxed);
                }
            } catch (...) {
                failed = true;
                throw;
            }
            tsan_release(&handoff);
        },
        tbb::simple_partitioner());
    tsan_acquire(&handoff);
    if (delivered.load() == count) sink.finish();

    RayCounters total;
    for (const RayCounters& c : counters) total += c;
    return total;
}

}  // namespace rayo
