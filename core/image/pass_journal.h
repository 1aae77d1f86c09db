#pragma once
// The finished passes of an interrupted progressive render (core/progressive.h), kept beside its
// output so that `rayo render --resume` goes on from them (docs/path-tracing.md, "Progressive
// renders"): OUTPUT.rayo-passes, a text header (a first line naming the format, the render's
// fingerprint as core/image/partial_render.h writes it, the passes, samples and seconds so far,
// the image's size and a checksum of the sums) and then the passes' sums as they are in memory
// (PassAccumulator: RGBA floats, then the luminance's doubles). The file is replaced whole (a
// temporary renamed over it), so it always holds a consistent set of passes: a `kill -9` loses
// at most the passes since the last one kept. Passes are kept from `keep_after` into the render
// on, then at most every `keep_after` seconds and never more often than four times the last
// write took (the sums are 32 bytes a pixel, 8 MB at 512²); a render shorter than that keeps
// nothing.
#include <chrono>
#include <memory>
#include <string>

#include "core/image/partial_render.h"
#include "core/progressive.h"

namespace rayo {

// OUTPUT.rayo-passes.
std::string pass_journal_path(const std::string& output);

class PassJournal : public ProgressiveCheckpoint {
  public:
    // A new journal of `output`'s passes; the file is written with the first pass kept.
    // InputError(output) when one exists already (it is resumed with --resume, or removed by the
    // user to start over).
    static std::unique_ptr<PassJournal> create(const std::string& output,
                                               const RenderFingerprint& fingerprint,
                                               std::chrono::steady_clock::duration keep_after);
    // The journal of `output`, read whole (its checksum checked). InputError(output) when there
    // is none, when it is not one of rayo's, when it is damaged, or when its fingerprint differs
    // from `fingerprint` (every difference named).
    static std::unique_ptr<PassJournal> resume(const std::string& output,
                                               const RenderFingerprint& fingerprint,
                                               std::chrono::steady_clock::duration keep_after);

    const std::string& path() const { return m_path; }
    // Passes on the disk (those of the earlier runs included).
    int passes_kept() const { return m_kept.passes; }
    int spp_kept() const { return m_kept.spp; }
    // Why keeping passes stopped (a write failed: a full disk), or empty; the render goes on.
    const std::string& failure() const { return m_failure; }
    // Removes the file (the output is written: the passes are no longer needed).
    void remove();
    // For tests (RAYO_TEST_INTERRUPT_PASSES, apps/cli): raise SIGINT once `passes` are kept, as
    // a user's Ctrl-C would then.
    void interrupt_after(int passes) { m_interrupt_after = passes; }

    bool restore(PassAccumulator& accumulator, ProgressiveResult& so_far, double& elapsed) override;
    void pass_finished(const PassAccumulator& accumulator, const ProgressiveResult& so_far,
                       double elapsed) override;

  private:
    PassJournal(const std::string& output, RenderFingerprint fingerprint,
                std::chrono::steady_clock::duration keep_after);
    void write(const PassAccumulator& accumulator, const ProgressiveResult& so_far, double elapsed);

    std::string m_path;
    RenderFingerprint m_fingerprint;
    std::chrono::steady_clock::duration m_keep_after;
    std::chrono::steady_clock::time_point m_start, m_last_write;
    std::chrono::steady_clock::duration m_write_took{0};
    ProgressiveResult m_kept;  // what the file holds
    double m_kept_seconds = 0.0;
    std::string m_saved;  // a resumed journal's sums, until restore() takes them
    std::string m_failure;
    int m_interrupt_after = 0;
};

}  // namespace rayo
