#pragma once
// A terminal progress bar with elapsed time and ETA, drawn on stderr by its own thread a few
// times a second; workers only add to an atomic counter. Silent when disabled.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

namespace rayo {

class ProgressReporter {
  public:
    ProgressReporter(uint64_t total_work, std::string title, bool enabled);
    ~ProgressReporter();  // finishes the bar (a final 100% line when enabled)
    ProgressReporter(const ProgressReporter&) = delete;
    ProgressReporter& operator=(const ProgressReporter&) = delete;

    void add(uint64_t work) { m_done.fetch_add(work, std::memory_order_relaxed); }
    void finish();

    // True when stderr is a terminal (the CLI's default for showing progress).
    static bool stderr_is_terminal();

  private:
    void draw(bool final_line);

    uint64_t m_total;
    std::string m_title;
    bool m_enabled;
    std::atomic<uint64_t> m_done{0};
    std::chrono::steady_clock::time_point m_start;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_stop = false;
    std::thread m_thread;
};

std::string format_duration(double seconds);

}  // namespace rayo
