#include "core/progress.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "core/stop_request.h"

namespace rayo {

std::string format_duration(double seconds) {
    char buffer[32];
    if (!std::isfinite(seconds) || seconds < 0.0) return "--";
    if (seconds < 60.0) {
        std::snprintf(buffer, sizeof buffer, "%.1fs", seconds);
    } else {
        const long total = static_cast<long>(seconds + 0.5);
        std::snprintf(buffer, sizeof buffer, "%ldm%02lds", total / 60, total % 60);
    }
    return buffer;
}

bool ProgressReporter::stderr_is_terminal() {
    return isatty(STDERR_FILENO) == 1;
}

ProgressReporter::ProgressReporter(uint64_t total_work, std::string title, bool enabled)
    : m_total(total_work > 0 ? total_work : 1),
      m_title(std::move(title)),
      m_enabled(enabled),
      m_start(std::chrono::steady_clock::now()) {
    if (!m_enabled) return;
    m_thread = std::thread([this] {
        std::unique_lock<std::mutex> lock(m_mutex);
        while (!m_wake.wait_for(lock, std::chrono::milliseconds(250), [this] { return m_stop; })) {
            draw(false);
        }
    });
}

ProgressReporter::~ProgressReporter() {
    finish();
}

void ProgressReporter::finish() {
    if (!m_enabled) return;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_stop) return;
        m_stop = true;
    }
    m_wake.notify_all();
    m_thread.join();
    draw(true);
}

void ProgressReporter::draw(bool final_line) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    // An interrupted render (core/stop_request.h) ends its bar where it stopped.
    const uint64_t done =
        final_line && !stop_requested() ? m_total : std::min(m_done.load(), m_total);
    const double fraction = static_cast<double>(done) / static_cast<double>(m_total);
    constexpr int kBarWidth = 40;
    const int filled = static_cast<int>(fraction * kBarWidth);
    std::string bar(filled, '#');
    bar.append(kBarWidth - filled, '.');
    const double eta = fraction > 0.0 ? elapsed / fraction - elapsed : NAN;
    std::fprintf(stderr, "\r%s [%s] %5.1f%% %s elapsed, ETA %s ", m_title.c_str(), bar.c_str(),
                 100.0 * fraction, format_duration(elapsed).c_str(),
                 final_line ? "0s" : format_duration(eta).c_str());
    if (final_line) std::fputc('\n', stderr);
    std::fflush(stderr);
}

}  // namespace rayo
