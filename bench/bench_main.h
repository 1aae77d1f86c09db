#pragma once
// The shared main() of rayo's Google Benchmark programs: the floating-point mode the renderer
// runs in (flush-to-zero, denormals-are-zero, as apps/main.cpp sets for Embree), then the runs.
#include <benchmark/benchmark.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#define RAYO_BENCHMARK_MAIN()                                                \
    int main(int argc, char** argv) {                                        \
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);                          \
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);                  \
        benchmark::Initialize(&argc, argv);                                  \
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;    \
        benchmark::RunSpecifiedBenchmarks();                                 \
        benchmark::Shutdown();                                               \
        return 0;                                                            \
    }
