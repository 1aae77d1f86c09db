#pragma once
// The tile-parallel render loop: tbb::parallel_for over square tiles, stratified samples per
// pixel from the stateless hash (core/sampling.h), per-thread ray counters merged at the end.
// Generic over the integrator (any type with `Vec3 radiance(const Ray&, RayCounters&) const`),
// so the hot path has no virtual call. The result does not depend on thread count or tile size:
// every pixel's samples are summed in a fixed order by the one task that owns the pixel.
#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "core/camera.h"
#include "core/film.h"
#include "core/progress.h"
#include "core/sampling.h"
#include "core/stats.h"

namespace rayo {

struct TileSettings {
    int spp = 1;
    int tile_size = 16;
};

template <typename Integrator>
RayCounters render_tiles(const Camera& camera, const Integrator& integrator,
                         const TileSettings& settings, Film& film,
                         ProgressReporter* progress = nullptr) {
    const int width = camera.width(), height = camera.height();
    const int tile = settings.tile_size > 0 ? settings.tile_size : 16;
    const auto spp = static_cast<uint32_t>(settings.spp > 0 ? settings.spp : 1);
    const float inverse_spp = 1.0f / static_cast<float>(spp);
    tbb::enumerable_thread_specific<RayCounters> counters;

    // Grain = one tile; simple_partitioner so tiles are exactly tile × tile.
    tbb::parallel_for(
        tbb::blocked_range2d<int>(0, height, tile, 0, width, tile),
        [&](const tbb::blocked_range2d<int>& range) {
            RayCounters& local = counters.local();
            for (int y = range.rows().begin(); y < range.rows().end(); ++y) {
                for (int x = range.cols().begin(); x < range.cols().end(); ++x) {
                    Vec3 sum(0.0f);
                    for (uint32_t s = 0; s < spp; ++s) {
                        const PixelOffset o = stratified_offset(x, y, s, spp);
                        const Ray ray = camera.generate_ray(static_cast<float>(x) + o.dx,
                                                            static_cast<float>(y) + o.dy);
                        sum += integrator.radiance(ray, local);
                    }
                    film.set(x, y, sum * inverse_spp);
                }
            }
            if (progress) progress->add(range.rows().size() * range.cols().size());
        },
        tbb::simple_partitioner());

    RayCounters total;
    for (const RayCounters& c : counters) total += c;
    return total;
}

}  // namespace rayo
