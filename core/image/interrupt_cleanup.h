#pragma once
// SIGINT and SIGTERM at any phase (parse, BVH build, render, write) end rayo at once with the
// shell's status 128 + signal (130, 143), after removing the temporary files being written, so
// that an interrupted run leaves no file behind under any name (docs/limits.md, "Signals").
// Files are written to temporary names and renamed (core/image/image_output.h), so the final
// name either holds a whole image or does not exist. While a resumable render hands out tiles
// (a GracefulInterrupt exists), the first signal only requests a stop (core/stop_request.h):
// the tiles in flight finish and reach the partial render (core/image/partial_render.h); a
// second signal ends rayo at once.
#include <string>

namespace rayo {

// Installs the handlers (the `rayo` executable's main); a signal ignored at start (a shell's
// background job, nohup) stays ignored. Also ignores SIGXFSZ, so that a write
// beyond the file-size limit fails with EFBIG and is reported instead of killing the process.
void install_interrupt_cleanup();

// Registers a temporary file for removal by the handlers while it exists; the destructor
// unregisters it. At most kMaxTemporaryFiles at once (further ones are not registered).
class TemporaryFileGuard {
  public:
    explicit TemporaryFileGuard(const std::string& path);
    ~TemporaryFileGuard();
    TemporaryFileGuard(const TemporaryFileGuard&) = delete;
    TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;

  private:
    int m_slot = -1;
};

constexpr int kMaxTemporaryFiles = 8;

// While one exists, the first SIGINT/SIGTERM calls request_stop(signal) (core/stop_request.h)
// and prints that rayo is finishing the tiles in flight; a further signal ends rayo as above.
// Outside it (parse, BVH build, final write) every signal ends rayo at once.
class GracefulInterrupt {
  public:
    GracefulInterrupt();
    ~GracefulInterrupt();
    GracefulInterrupt(const GracefulInterrupt&) = delete;
    GracefulInterrupt& operator=(const GracefulInterrupt&) = delete;
};

}  // namespace rayo
