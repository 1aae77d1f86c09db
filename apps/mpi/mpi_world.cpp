#include "apps/mpi/mpi_world.h"

#include <cstdlib>
#include <ostream>

#if RAYO_HAVE_MPI
#include <mpi.h>
#endif

namespace rayo {
namespace {

int g_rank = 0;
int g_size = 1;

#if RAYO_HAVE_MPI
bool g_initialised = false;

// Open MPI's launcher sets OMPI_COMM_WORLD_SIZE, PMIx launchers PMIX_RANK, Hydra/PMI ones
// PMI_SIZE: a process started any other way stays a world of one without loading MPI's
// runtime.
bool launched_by_mpi() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"}) {
        if (std::getenv(name) != nullptr) return true;
    }
    return false;
}

void finalize() {
    if (g_initialised) MPI_Finalize();
}
#endif

}  // namespace

void MpiWorld::init(int& argc, char**& argv) {
#if RAYO_HAVE_MPI
    if (!launched_by_mpi()) return;
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    g_initialised = true;
    std::atexit(finalize);
    MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &g_size);
#else
    (void)argc;
    (void)argv;
#endif
}

int MpiWorld::rank() {
    return g_rank;
}

int MpiWorld::size() {
    return g_size;
}

bool MpiWorld::available() {
    return RAYO_HAVE_MPI != 0;
}

int MpiWorld::agree_on_failure(bool failed, const std::string& message, int exit_code,
                               std::ostream& err) {
    if (!distributed()) {
        if (failed) err << message;
        return failed ? exit_code : 0;
    }
#if RAYO_HAVE_MPI
    int candidate = failed ? g_rank : g_size;
    int first = g_size;
    MPI_Allreduce(&candidate, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == g_size) return 0;
    if (first == g_rank) {
        err << message;
        err.flush();
    }
    int code = failed ? exit_code : 0;
    MPI_Bcast(&code, 1, MPI_INT, first, MPI_COMM_WORLD);
    return code;
#else
    return 0;
#endif
}

void MpiWorld::abort(int exit_code) {
#if RAYO_HAVE_MPI
    if (g_initialised) MPI_Abort(MPI_COMM_WORLD, exit_code);
#endif
    std::_Exit(exit_code);
}

}  // namespace rayo
