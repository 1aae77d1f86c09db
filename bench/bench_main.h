#pragma once
// The shared main() of rayo's Google Benchmark programs: the floating-point mode the renderer
// runs in (core/float_mode.h), then the runs.
#include <benchmark/benchmark.h>

#include "core/float_mode.h"

#define RAYO_BENCHMARK_MAIN()                                             \
    int main(int argc, char** argv) {                                     \
        rayo::set_flush_denormals_to_zero();                              \
        benchmark::Initialize(&argc, argv);                               \
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1; \
        benchmark::RunSpecifiedBenchmarks();                              \
        benchmark::Shutdown();                                            \
        return 0;                                                         \
    }
