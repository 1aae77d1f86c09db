// The `rayo` executable: sets the floating-point mode Embree wants and runs the CLI.
#include <iostream>

#include "apps/cli/cli.h"
#include "core/float_mode.h"

int main(int argc, char** argv) {
    rayo::set_flush_denormals_to_zero();
    return rayo::run_cli(argc, argv, std::cout, std::cerr);
}
