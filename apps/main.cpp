// The `rayo` executable: sets the floating-point mode Embree wants and runs the CLI.
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <iostream>

#include "apps/cli.h"

int main(int argc, char** argv) {
    // Flush-to-zero and denormals-are-zero, as Embree recommends (DESIGN.md "Hot-path rules").
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    return rayo::run_cli(argc, argv, std::cout, std::cerr);
}
