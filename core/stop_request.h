#pragma once
// A request to stop rendering at the next tile boundary: set by the first SIGINT/SIGTERM of a
// resumable render (core/image/interrupt_cleanup.h), read by the tile loop (core/render.h),
// which then hands out no further tile and lets the tiles in flight finish
// (docs/high-resolution.md, "Interrupt and resume"). A lock-free atomic: safe to set from a
// signal handler.
#include <atomic>

namespace rayo {

// 0: no request; else the signal number that asked to stop.
inline std::atomic<int> g_stop_signal{0};

inline void request_stop(int signal_number) {
    g_stop_signal.store(signal_number, std::memory_order_relaxed);
}
inline int stop_signal() {
    return g_stop_signal.load(std::memory_order_relaxed);
}
inline bool stop_requested() {
    return stop_signal() != 0;
}

}  // namespace rayo
