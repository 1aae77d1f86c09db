#pragma once
// The processes of one render (docs/distributed.md). Started by `mpirun -np N` (and built with
// Open MPI), rayo runs as N ranks of MPI_COMM_WORLD; started any other way, or built without
// MPI, it is a world of one and never touches MPI. Only the main thread calls MPI
// (MPI_THREAD_FUNNELED).
#include <iosfwd>
#include <string>

namespace rayo {

class MpiWorld {
  public:
    // Initialises MPI when this process was launched by an MPI launcher. Call once, first
    // thing in main(); the world is finalised at exit.
    static void init(int& argc, char**& argv);
    static int rank();
    static int size();
    static bool distributed() { return size() > 1; }
    // Whether this build can run distributed (it was built with MPI).
    static bool available();

    // Collective. Every rank passes whether it failed and, if so, its message and exit code;
    // every rank gets back the lowest failing rank's exit code (0 when none failed). That rank
    // alone prints its message, so an error that every rank meets is printed once.
    static int agree_on_failure(bool failed, const std::string& message, int exit_code,
                                std::ostream& err);
    // Ends every rank at once (an error during the distributed render, where the others would
    // wait for this one forever).
    [[noreturn]] static void abort(int exit_code);
};

}  // namespace rayo
