// The `rayo` executable: sets the floating-point mode Embree wants, installs the SIGINT/SIGTERM
// cleanup and runs the CLI.
#include <iostream>

#include "apps/cli/cli.h"
#include "core/float_mode.h"
#include "core/image/interrupt_cleanup.h"

int main(int argc, char** argv) {
    rayo::set_flush_denormals_to_zero();
    rayo::install_interrupt_cleanup();
    return rayo::run_cli(argc, argv, std::cout, std::cerr);
}
