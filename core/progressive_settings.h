#pragma once
// The settings and the result of a progressive render (core/progressive.h), apart from the pass
// loop so that the scene description and the render's result hold them without the tile loop's
// headers.
#include <cstdint>
#include <limits>

#include "core/stats.h"

namespace rayo {

// The largest progressive render: 2^26 pixels (8192²), whose passes' sums take 2 GiB at 32 bytes
// a pixel (PassAccumulator).
constexpr long long kMaxProgressivePixels = 1LL << 26;

// Off unless a time limit or a noise target is set.
struct ProgressiveSettings {
    float time_limit = 0.0f;    // seconds; 0: none
    float noise_target = 0.0f;  // relative RMS standard error; 0: none
    int pass_spp = 4;           // samples per pixel of each pass
    // The most samples a pixel gets (whole passes): Cycles' default cap, so that a target the
    // scene cannot reach (fireflies keep a glass scene's noise up) still ends.
    int max_spp = 4096;

    bool enabled() const { return time_limit > 0.0f || noise_target > 0.0f; }
};

enum class ProgressiveStop { Samples, TimeLimit, NoiseTarget, Interrupted };

inline const char* progressive_stop_name(ProgressiveStop stop) {
    switch (stop) {
        case ProgressiveStop::Samples:
            return "the sample cap";
        case ProgressiveStop::TimeLimit:
            return "the time limit";
        case ProgressiveStop::NoiseTarget:
            return "the noise target";
        case ProgressiveStop::Interrupted:
            return "an interrupt";
    }
    return "?";
}

struct ProgressiveResult {
    int passes = 0;    // complete passes in the image
    uint32_t spp = 0;  // samples per pixel in the image: passes × pass_spp
    // The estimate after the last pass; NaN before the second.
    double noise = std::numeric_limits<double>::quiet_NaN();
    ProgressiveStop stop = ProgressiveStop::Samples;
    RayCounters counters;
};

}  // namespace rayo
