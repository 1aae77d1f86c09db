// The `rayo` executable: sets the floating-point mode Embree wants and the allocator settings of
// the image writers, installs the SIGINT/SIGTERM cleanup and runs the CLI; under mpirun, one rank
// of a distributed render.
#include <iostream>

#include "apps/cli/cli.h"
#include "apps/mpi/mpi_world.h"
#include "core/float_mode.h"
#include "core/image/allocator_tuning.h"
#include "core/image/interrupt_cleanup.h"

int main(int argc, char** argv) {
    rayo::MpiWorld::init(argc, argv);  // a world of one unless started by mpirun
    rayo::set_flush_denormals_to_zero();
    rayo::tune_allocator_for_image_writing();
    rayo::install_interrupt_cleanup();
    return rayo::run_cli(argc, argv, std::cout, std::cerr);
}
