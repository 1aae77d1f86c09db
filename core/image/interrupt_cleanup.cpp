#include "core/image/interrupt_cleanup.h"

#include <unistd.h>

#include <atomic>
#include <climits>
#include <csignal>
#include <cstring>

#include "core/stop_request.h"

namespace rayo {

namespace {

// Slots the handler reads: a path is visible to it only once fully copied (state kActive).
// Lock-free atomics and unlink/write/_exit are async-signal-safe.
enum SlotState : int { kFree = 0, kFilling = 1, kActive = 2 };
std::atomic<int> g_state[kMaxTemporaryFiles];
char g_path[kMaxTemporaryFiles][PATH_MAX];
std::atomic<bool> g_graceful{false};

void write_stderr(const char* text) {
    ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;
}

extern "C" void on_interrupt(int signal_number) {
    if (g_graceful.load() && !stop_requested()) {
        request_stop(signal_number);
        write_stderr(signal_number == SIGINT
                         ? "\nrayo: interrupted (SIGINT): finishing the tiles in flight "
                           "(again to stop at once)\n"
                         : "\nrayo: terminated (SIGTERM): finishing the tiles in flight "
                           "(again to stop at once)\n");
        return;
    }
    for (int i = 0; i < kMaxTemporaryFiles; ++i) {
        if (g_state[i].load() == kActive) ::unlink(g_path[i]);
    }
    write_stderr(signal_number == SIGINT ? "\nrayo: interrupted (SIGINT)\n"
                                         : "\nrayo: terminated (SIGTERM)\n");
    ::_exit(128 + signal_number);
}

}  // namespace

void install_interrupt_cleanup() {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaddset(&action.sa_mask, SIGINT);
    sigaddset(&action.sa_mask, SIGTERM);
    for (const int signal_number : {SIGINT, SIGTERM}) {
        // A signal ignored at start stays ignored (a shell's background job, nohup).
        struct sigaction previous {};
        sigaction(signal_number, nullptr, &previous);
        if (previous.sa_handler != SIG_IGN) sigaction(signal_number, &action, nullptr);
    }
    std::signal(SIGXFSZ, SIG_IGN);
}

GracefulInterrupt::GracefulInterrupt() {
    g_graceful.store(true);
}

GracefulInterrupt::~GracefulInterrupt() {
    g_graceful.store(false);
}

TemporaryFileGuard::TemporaryFileGuard(const std::string& path) {
    if (path.size() >= PATH_MAX) return;
    for (int i = 0; i < kMaxTemporaryFiles; ++i) {
        int expected = kFree;
        if (g_state[i].compare_exchange_strong(expected, kFilling)) {
            std::memcpy(g_path[i], path.c_str(), path.size() + 1);
            g_state[i].store(kActive);
            m_slot = i;
            return;
        }
    }
}

TemporaryFileGuard::~TemporaryFileGuard() {
    if (m_slot >= 0) g_state[m_slot].store(kFree);
}

}  // namespace rayo
