#pragma once
// An integer option's value and its bounds, shared by the command line (apps/cli/cli.cpp) and
// the Python module (apps/python/rayo_module.cpp), so that `rayo bench suite --size 0` and
// `rayo.bench_suite(size=0)` refuse the same values with the same message.
#include <charconv>
#include <string>

#include "apps/cli/usage_error.h"

namespace rayo {

struct IntRange {
    int min = 0;
    int max = 0;
};

// `rayo bench suite`: --size (the SPD size), --width (square images), --threads.
inline constexpr IntRange kSuiteSizeRange{1, 64};
inline constexpr IntRange kSuiteWidthRange{2, 16384};
inline constexpr IntRange kSuiteThreadsRange{1, 4096};
inline constexpr IntRange kSuiteRepetitionsRange{1, 1000};
// `rayo bench accuracy --size` (square images).
inline constexpr IntRange kAccuracySizeRange{16, 4096};
// `rayo bench convergence`: --width, and --reference-spp, --max-spp, --whitted-spp (render.spp's
// bounds, apps/scene/scene_description.h kMaxSpp); --threads as the suite's.
inline constexpr IntRange kConvergenceWidthRange{8, 4096};
inline constexpr IntRange kConvergenceSppRange{1, 1 << 16};

// `text` as an integer in [min_value, max_value], or the UsageError "--size: expected an integer
// in [1, 64], got '0'".
inline int parse_int_flag(const std::string& flag, const std::string& text, int min_value,
                          int max_value) {
    int value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || value < min_value || value > max_value) {
        throw UsageError(flag + ": expected an integer in [" + std::to_string(min_value) + ", " +
                         std::to_string(max_value) + "], got '" + text + "'");
    }
    return value;
}

inline int parse_int_flag(const std::string& flag, const std::string& text, IntRange range) {
    return parse_int_flag(flag, text, range.min, range.max);
}

// `rayo bench convergence`: the reference must have more samples than any row it measures, or
// its own noise would be most of the error measured.
inline void check_convergence_spp(int max_spp, int reference_spp) {
    if (max_spp >= reference_spp) {
        throw UsageError("--max-spp: expected fewer samples than --reference-spp " +
                         std::to_string(reference_spp) + ", got " + std::to_string(max_spp));
    }
}

}  // namespace rayo
