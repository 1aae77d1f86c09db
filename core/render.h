#pragma once
// The tile-parallel render loop: tbb::parallel_for over square tiles, stratified samples per
// pixel from the stateless hash (core/sampling.h), per-thread ray counters merged at the end.
// Generic over the integrator (any type with `Vec3 radiance(const Ray&, RayCounters&) const`
// and `void radiance_coherent(const Ray*, int, Vec3*, RayCounters&) const`), so the hot path has
// no virtual call. The result does not depend on thread count, tile size or the coherent path:
// every pixel's samples are summed in a fixed order by the one task that owns the pixel, and the
// coherent path computes the same values as the single-ray one.
#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "core/camera.h"
#include "core/film.h"
#include "core/progress.h"
#include "core/sampling.h"
#include "core/stats.h"
#include "core/tsan_handoff.h"

namespace rayo {

struct TileSettings {
    int spp = 1;
    int tile_size = 16;
    // Camera rays of a tile in batches through the integrator's coherent path (Embree streams);
    // false: one ray at a time (the reference the coherent path is tested against).
    bool coherent = true;
};

// Camera ray for sample `s` of pixel (x, y): stratified jitter, the pixel centre when spp = 1.
inline Ray pixel_ray(const Camera& camera, int x, int y, uint32_t s, uint32_t spp) {
    const PixelOffset o =
        stratified_offset(static_cast<uint32_t>(x), static_cast<uint32_t>(y), s, spp);
    return camera.generate_ray(static_cast<float>(x) + o.dx, static_cast<float>(y) + o.dy);
}

template <typename Integrator>
RayCounters render_tiles(const Camera& camera, const Integrator& integrator,
                         const TileSettings& settings, Film& film,
                         ProgressReporter* progress = nullptr) {
    const int width = camera.width(), height = camera.height();
    const int tile = settings.tile_size > 0 ? settings.tile_size : 16;
    const auto spp = static_cast<uint32_t>(settings.spp > 0 ? settings.spp : 1);
    const float inverse_spp = 1.0f / static_cast<float>(spp);
    tbb::enumerable_thread_specific<RayCounters> counters;

    // The caller's writes (film, counters) before every task; every task before the merge.
    int handoff = 0;
    tsan_release(&handoff);
    // Grain = one tile; simple_partitioner splits down to tiles of at most tile × tile.
    tbb::parallel_for(
        tbb::blocked_range2d<int>(0, height, tile, 0, width, tile),
        [&](const tbb::blocked_range2d<int>& range) {
            tsan_acquire(&handoff);
            RayCounters& local = counters.local();
            if (!settings.coherent) {
                for (int y = range.rows().begin(); y < range.rows().end(); ++y) {
                    for (int x = range.cols().begin(); x < range.cols().end(); ++x) {
                        Vec3 sum(0.0f);
                        for (uint32_t s = 0; s < spp; ++s) {
                            sum += integrator.radiance(pixel_ray(camera, x, y, s, spp), local);
                        }
                        film.set(x, y, sum * inverse_spp);
                    }
                }
            } else {
                // The tile's pixels in row-major chunks of kChunk; each sample index of a chunk
                // is one coherent batch. Sums run over samples in the same order as above.
                constexpr int kChunk = 64;
                const int columns = static_cast<int>(range.cols().size());
                const int pixels = static_cast<int>(range.rows().size()) * columns;
                Ray rays[kChunk];
                Vec3 radiance[kChunk], sum[kChunk];
                for (int first = 0; first < pixels; first += kChunk) {
                    const int n = std::min(kChunk, pixels - first);
                    for (int i = 0; i < n; ++i) sum[i] = Vec3(0.0f);
                    for (uint32_t s = 0; s < spp; ++s) {
                        for (int i = 0; i < n; ++i) {
                            rays[i] =
                                pixel_ray(camera, range.cols().begin() + (first + i) % columns,
                                          range.rows().begin() + (first + i) / columns, s, spp);
                        }
                        integrator.radiance_coherent(rays, n, radiance, local);
                        for (int i = 0; i < n; ++i) sum[i] += radiance[i];
                    }
                    for (int i = 0; i < n; ++i) {
                        film.set(range.cols().begin() + (first + i) % columns,
                                 range.rows().begin() + (first + i) / columns,
                                 sum[i] * inverse_spp);
                    }
                }
            }
            if (progress) progress->add(range.rows().size() * range.cols().size());
            tsan_release(&handoff);
        },
        tbb::simple_partitioner());
    tsan_acquire(&handoff);

    RayCounters total;
    for (const RayCounters& c : counters) total += c;
    return total;
}

}  // namespace rayo
