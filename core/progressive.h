#pragma once
// Progressive rendering (docs/path-tracing.md, "Progressive renders"): the whole image in passes
// of a few stratified samples per pixel, accumulated until a time limit, an estimated noise level
// or a cap on the samples is reached, then handed to the render's sink tile by tile. Pass k takes
// the samples k·pass_spp … (k + 1)·pass_spp − 1 of every pixel (core/render.h first_sample), so
// the image is the same bits for any thread count and tile size, and one pass is the plain
// render of pass_spp samples.
//
// The noise estimate is the method of batch means (Law & Kelton 2000): each pass gives an
// independent estimate of every pixel's luminance, and the spread of those estimates over n passes
// gives the variance of their mean, s²/n. The image's figure is the root mean square of the pixels'
// standard errors over the image's mean luminance: the relative RMS error that
// docs/path-tracing.md's convergence chart measures against a reference.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/luminance.h"
#include "core/progress.h"
#include "core/progressive_settings.h"
#include "core/render.h"
#include "core/stop_request.h"
#include "core/tile_distribution.h"
#include "core/tile_grid.h"
#include "core/tile_sink.h"

namespace rayo {

// A noise estimate needs passes to compare; a few more keep it from stopping on a lucky pair.
constexpr int kMinNoisePasses = 4;

// The sink of every pass: per pixel the sum of the passes' RGBA and the sum and sum of squares
// of their luminance (double: the variance is their difference). 32 bytes a pixel.
class PassAccumulator : public TileSink {
  public:
    PassAccumulator(int width, int height)
        : m_width(width),
          m_rgba(static_cast<size_t>(width) * height * 4, 0.0f),
          m_luminance(static_cast<size_t>(width) * height * 2, 0.0) {}

    // Tiles of one pass; concurrent calls write disjoint pixels.
    void write_tile(const Tile& tile, const float* rgba) override {
        for (int row = 0; row < tile.height; ++row) {
            for (int column = 0; column < tile.width; ++column) {
                const float* p = rgba + (static_cast<size_t>(row) * tile.width + column) * 4;
                const size_t pixel =
                    static_cast<size_t>(tile.y0 + row) * m_width + tile.x0 + column;
                for (int c = 0; c < 4; ++c) m_rgba[pixel * 4 + c] += p[c];
                const double y = luminance(p[0], p[1], p[2]);
                m_luminance[pixel * 2] += y;
                m_luminance[pixel * 2 + 1] += y * y;
            }
        }
    }

    // The relative RMS standard error of the mean of `passes` passes (batch means; see above):
    // NaN below two passes, 0 for an image of mean luminance 0.
    double relative_noise(int passes) const {
        if (passes < 2) return std::numeric_limits<double>::quiet_NaN();
        const double n = passes;
        double variance_sum = 0.0, mean_sum = 0.0;
        for (size_t pixel = 0; pixel < m_luminance.size() / 2; ++pixel) {
            const double sum = m_luminance[pixel * 2], squares = m_luminance[pixel * 2 + 1];
            // Sample variance of the pass estimates over n, the variance of their mean.
            variance_sum += std::max(0.0, squares - sum * sum / n) / (n - 1.0) / n;
            mean_sum += sum / n;
        }
        if (mean_sum <= 0.0) return 0.0;
        const double pixels = static_cast<double>(m_luminance.size() / 2);
        return std::sqrt(variance_sum / pixels) / (mean_sum / pixels);
    }

    // The mean of `passes` passes to `sink`, tile by tile in the grid's order.
    void deliver(const TileGrid& grid, int passes, TileSink& sink) const {
        const float inverse = 1.0f / static_cast<float>(passes);
        std::vector<float> tile_rgba;
        sink.begin(grid);
        for (int index = 0; index < grid.tile_count(); ++index) {
            const Tile tile = grid.tile(index);
            tile_rgba.resize(tile.pixel_count() * 4);
            for (int row = 0; row < tile.height; ++row) {
                const size_t first = (static_cast<size_t>(tile.y0 + row) * m_width + tile.x0) * 4;
                for (int i = 0; i < tile.width * 4; ++i) {
                    tile_rgba[static_cast<size_t>(row) * tile.width * 4 + i] =
                        m_rgba[first + i] * inverse;
                }
            }
            sink.write_tile(tile, tile_rgba.data());
        }
        sink.finish();
    }

    int width() const { return m_width; }
    // The sums themselves, for a checkpoint to save and restore (ProgressiveCheckpoint):
    // RGBA floats, 4 a pixel, and the luminance's sum and sum of squares, 2 doubles a pixel.
    std::vector<float>& rgba_sums() { return m_rgba; }
    std::vector<double>& luminance_sums() { return m_luminance; }
    const std::vector<float>& rgba_sums() const { return m_rgba; }
    const std::vector<double>& luminance_sums() const { return m_luminance; }

  private:
    int m_width;
    std::vector<float> m_rgba;
    std::vector<double> m_luminance;
};

// Where a progressive render keeps its finished passes so that a later run goes on from them
// (`rayo render --resume`: core/image/pass_journal.h).
class ProgressiveCheckpoint {
  public:
    virtual ~ProgressiveCheckpoint() = default;
    // Before the first pass: the passes an earlier run kept, into `accumulator` (sized for the
    // image), `so_far` (passes, spp, noise) and `elapsed` (its seconds); false when none.
    virtual bool restore(PassAccumulator& accumulator, ProgressiveResult& so_far,
                         double& elapsed) = 0;
    // After each finished pass: the passes so far, which the checkpoint keeps when it chooses
    // (how often is its own rule).
    virtual void pass_finished(const PassAccumulator& accumulator, const ProgressiveResult& so_far,
                               double elapsed) = 0;
};

// "pass 3, 12 spp, noise 4.1%" (the progress bar's title).
inline std::string pass_title(const ProgressiveResult& so_far, int pass_spp) {
    std::ostringstream title;
    title << "pass " << so_far.passes + 1 << ", " << so_far.spp + pass_spp << " spp";
    if (!std::isnan(so_far.noise)) {
        title.precision(2);
        title << ", noise " << std::fixed << so_far.noise * 100.0 << "%";
    }
    return title.str();
}

// After a pass: why the passes stop there, or nothing to go on (render_progressive's rule).
inline std::optional<ProgressiveStop> progressive_stop(const ProgressiveSettings& progressive,
                                                       const ProgressiveResult& so_far,
                                                       double elapsed, uint32_t max_spp) {
    if (stop_requested()) return ProgressiveStop::Interrupted;
    if (progressive.noise_target > 0.0f && so_far.passes >= kMinNoisePasses &&
        so_far.noise <= progressive.noise_target) {
        return ProgressiveStop::NoiseTarget;
    }
    if (progressive.time_limit > 0.0f && elapsed >= progressive.time_limit) {
        return ProgressiveStop::TimeLimit;
    }
    if (static_cast<uint64_t>(so_far.spp) + static_cast<uint32_t>(progressive.pass_spp) > max_spp) {
        return ProgressiveStop::Samples;
    }
    return std::nullopt;
}

// Renders passes of `progressive.pass_spp` samples (settings.spp is ignored) until the first of:
// the noise estimate at or below the target (after kMinNoisePasses), the time limit crossed
// by the pass just finished, `max_spp` reached, or a stop request (core/stop_request.h), which
// drops the unfinished pass and delivers nothing. Otherwise the mean of the passes goes to
// `sink`. The caller checks the image fits in memory (PassAccumulator: 32 bytes a pixel).
// With a `distribution` (MPI ranks, docs/distributed.md) each pass's tiles are shared out and
// gathered on the writing process, which alone accumulates, estimates the noise, decides for
// every process whether another pass follows (TileDistribution::follow_writer) and delivers;
// `processes` then sums each process's work over the passes. The passes are the same bits as
// in one process, so the image and the number of passes are too. A `checkpoint` (one process)
// gives the passes of an earlier run to start from and keeps each finished pass: a resumed
// render is the same bits as one never interrupted, and its time limit counts the earlier
// runs' seconds.
template <typename Camera, typename Integrator>
ProgressiveResult render_progressive(const Camera& camera, const Integrator& integrator,
                                     TileSettings settings, const ProgressiveSettings& progressive,
                                     uint32_t max_spp, TileSink& sink, bool show_progress,
                                     TileDistribution* distribution = nullptr,
                                     std::vector<ProcessWork>* processes = nullptr,
                                     ProgressiveCheckpoint* checkpoint = nullptr) {
    const TileGrid grid(camera.width(), camera.height(), settings.tile_size);
    const auto pass_spp = static_cast<uint32_t>(progressive.pass_spp);
    const uint64_t pixels = static_cast<uint64_t>(camera.width()) * camera.height();
    const bool writer = distribution == nullptr || distribution->writes_image();
    PassAccumulator accumulator(writer ? camera.width() : 1, writer ? camera.height() : 1);
    settings.spp = progressive.pass_spp;
    settings.aa = AntiAliasing::Stratified;
    ProgressiveResult result;
    double earlier = 0.0;  // seconds of the runs before a resume
    if (checkpoint && writer) checkpoint->restore(accumulator, result, earlier);
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return earlier +
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    // Resumed past its stopping rule (a lower cap or limit than the run that kept the passes):
    // the passes kept are the image.
    bool done = false;
    if (result.passes > 0) {
        const std::optional<ProgressiveStop> stop =
            progressive_stop(progressive, result, elapsed(), max_spp);
        done = stop && *stop != ProgressiveStop::Interrupted;
        if (done) result.stop = *stop;
    }
    while (!done) {
        settings.first_sample = result.spp;
        {
            ProgressReporter progress(pixels, pass_title(result, progressive.pass_spp),
                                      show_progress && writer);
            if (distribution == nullptr) {
                result.counters +=
                    render_tiles(camera, integrator, settings, accumulator, &progress);
            } else {
                const auto render_chunk = [&](const std::vector<int>& list, TileSink& chunk) {
                    return render_tiles(camera, integrator, settings, chunk, nullptr, list);
                };
                result.counters +=
                    distribution->render(grid, {}, render_chunk, accumulator, &progress);
                if (processes) {
                    const std::vector<ProcessWork>& pass = distribution->work();
                    processes->resize(pass.size());
                    for (size_t rank = 0; rank < pass.size(); ++rank) {
                        (*processes)[rank].tiles += pass[rank].tiles;
                        (*processes)[rank].counters += pass[rank].counters;
                        (*processes)[rank].seconds += pass[rank].seconds;
                    }
                }
            }
        }
        std::optional<ProgressiveStop> stop;
        if (writer) {
            if (!stop_requested()) {
                ++result.passes;
                result.spp += pass_spp;
                result.noise = accumulator.relative_noise(result.passes);
                if (checkpoint) checkpoint->pass_finished(accumulator, result, elapsed());
            }
            stop = progressive_stop(progressive, result, elapsed(), max_spp);
        }
        if (distribution) {
            // -1: another pass; else the writer's ProgressiveStop, which every process follows.
            const int decision = distribution->follow_writer(stop ? static_cast<int>(*stop) : -1);
            if (!writer) {
                if (decision >= 0) stop = static_cast<ProgressiveStop>(decision);
                ++result.passes;
                result.spp += pass_spp;
            }
        }
        if (!stop) continue;
        result.stop = *stop;
        if (result.stop == ProgressiveStop::Interrupted) return result;
        done = true;
    }
    if (writer) accumulator.deliver(grid, result.passes, sink);
    return result;
}

}  // namespace rayo
