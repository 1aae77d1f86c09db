#include "core/image/pass_journal.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/error.h"

namespace rayo {

namespace {

constexpr const char* kMagicLine = "rayo progressive passes 1";
constexpr size_t kMaxHeaderBytes = size_t(1) << 20;

// The sums' checksum: the RGBA floats' bytes and the luminance doubles' bytes (each a multiple
// of 8), combined.
uint64_t sums_checksum(const void* rgba, size_t rgba_bytes, const void* luminance,
                       size_t luminance_bytes) {
    return checksum64(rgba, rgba_bytes) * 0x100000001b3ULL ^ checksum64(luminance, luminance_bytes);
}

}  // namespace

std::string pass_journal_path(const std::string& output) {
    return output + ".rayo-passes";
}

PassJournal::PassJournal(const std::string& output, RenderFingerprint fingerprint,
                         std::chrono::steady_clock::duration keep_after)
    : m_path(pass_journal_path(output)),
      m_fingerprint(std::move(fingerprint)),
      m_keep_after(keep_after),
      m_start(std::chrono::steady_clock::now()) {}

std::unique_ptr<PassJournal> PassJournal::create(const std::string& output,
                                                 const RenderFingerprint& fingerprint,
                                                 std::chrono::steady_clock::duration keep_after) {
    std::unique_ptr<PassJournal> journal(new PassJournal(output, fingerprint, keep_after));
    struct stat info {};
    if (::lstat(journal->m_path.c_str(), &info) == 0) {
        throw InputError(output,
                         "the passes of an interrupted progressive render of this output "
                         "are kept in '" +
                             journal->m_path +
                             "': continue it with --resume, or remove it to start over");
    }
    return journal;
}

std::unique_ptr<PassJournal> PassJournal::resume(const std::string& output,
                                                 const RenderFingerprint& fingerprint,
                                                 std::chrono::steady_clock::duration keep_after) {
    std::unique_ptr<PassJournal> journal(new PassJournal(output, fingerprint, keep_after));
    const std::string& path = journal->m_path;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw InputError(output, "--resume: no passes of a progressive render of this output ('" +
                                     path + "' " +
                                     (errno == ENOENT ? std::string("does not exist")
                                                      : std::string(std::strerror(errno))) +
                                     ")");
    }
    // The header: text lines up to "end".
    std::string header, line;
    bool ended = false;
    while (header.size() < kMaxHeaderBytes && std::getline(in, line)) {
        if (line == "end") {
            ended = true;
            break;
        }
        header += line + "\n";
    }
    const auto damaged = [&](const std::string& why) {
        return InputError(
            output, "--resume: '" + path + "' " + why + "; remove it to start the render over");
    };
    if (header.compare(0, std::strlen(kMagicLine) + 1, std::string(kMagicLine) + "\n") != 0)
        throw damaged("is not the passes of a progressive render of rayo");
    if (!ended) throw damaged("is cut short in its header");
    RenderFingerprint saved = parse_fingerprint(header.substr(header.find('\n') + 1));
    // The state entries follow the fingerprint's.
    ProgressiveResult& kept = journal->m_kept;
    uint64_t checksum = 0;
    int found = 0, width = 0, height = 0;
    for (auto it = saved.begin(); it != saved.end();) {
        std::istringstream value(it->second);
        if (it->first == "= passes") {
            found += static_cast<bool>(value >> kept.passes);
        } else if (it->first == "= spp") {
            found += static_cast<bool>(value >> kept.spp);
        } else if (it->first == "= seconds") {
            found += static_cast<bool>(value >> journal->m_kept_seconds);
        } else if (it->first == "= size") {
            char x = 0;
            found += static_cast<bool>(value >> width >> x >> height);
        } else if (it->first == "= checksum") {
            found += static_cast<bool>(value >> std::hex >> checksum);
        } else {
            ++it;
            continue;
        }
        it = saved.erase(it);
    }
    if (found != 5 || kept.passes < 1 || kept.spp < 1 || width < 1 || height < 1 ||
        static_cast<long long>(width) * height > kMaxProgressivePixels) {
        throw damaged("has a damaged header");
    }
    const std::string differences = fingerprint_differences(saved, fingerprint, "kept passes");
    if (!differences.empty()) {
        throw InputError(output, "--resume: the passes kept in '" + path +
                                     "' were rendered with other settings:" + differences +
                                     "\nresume with the same scene and settings, or remove it "
                                     "to start over");
    }
    const size_t pixels = static_cast<size_t>(width) * height;
    const size_t body = pixels * (4 * sizeof(float) + 2 * sizeof(double));
    journal->m_saved.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (journal->m_saved.size() != body) {
        throw damaged("holds " + std::to_string(journal->m_saved.size()) +
                      " bytes of sums where its header says " + std::to_string(body));
    }
    const size_t rgba_bytes = pixels * 4 * sizeof(float);
    const char* bytes = journal->m_saved.data();
    if (sums_checksum(bytes, rgba_bytes, bytes + rgba_bytes, body - rgba_bytes) != checksum)
        throw damaged("is damaged (its sums do not match their checksum)");
    return journal;
}

bool PassJournal::restore(PassAccumulator& accumulator, ProgressiveResult& so_far,
                          double& elapsed) {
    if (m_saved.empty()) return false;
    std::vector<float>& rgba = accumulator.rgba_sums();
    std::vector<double>& luminance = accumulator.luminance_sums();
    if (rgba.size() * sizeof(float) + luminance.size() * sizeof(double) != m_saved.size()) {
        throw std::logic_error("PassJournal::restore: the image is not the journal's size");
    }
    std::memcpy(rgba.data(), m_saved.data(), rgba.size() * sizeof(float));
    std::memcpy(luminance.data(), m_saved.data() + rgba.size() * sizeof(float),
                luminance.size() * sizeof(double));
    m_saved.clear();
    m_saved.shrink_to_fit();
    so_far.passes = m_kept.passes;
    so_far.spp = m_kept.spp;
    so_far.noise = accumulator.relative_noise(so_far.passes);
    elapsed = m_kept_seconds;
    return true;
}

void PassJournal::pass_finished(const PassAccumulator& accumulator, const ProgressiveResult& so_far,
                                double elapsed) {
    if (!m_failure.empty()) return;
    const auto now = std::chrono::steady_clock::now();
    const bool first = m_last_write == std::chrono::steady_clock::time_point{};
    const auto since = now - (first ? m_start : m_last_write);
    if (since < m_keep_after || since < 4 * m_write_took) return;
    write(accumulator, so_far, elapsed);
    m_write_took = std::chrono::steady_clock::now() - now;
    m_last_write = std::chrono::steady_clock::now();
    if (m_interrupt_after > 0 && m_kept.passes >= m_interrupt_after) {
        m_interrupt_after = 0;
        std::raise(SIGINT);
    }
}

void PassJournal::write(const PassAccumulator& accumulator, const ProgressiveResult& so_far,
                        double elapsed) {
    const std::vector<float>& rgba = accumulator.rgba_sums();
    const std::vector<double>& luminance = accumulator.luminance_sums();
    std::ostringstream header;
    header << kMagicLine << "\n"
           << fingerprint_text(m_fingerprint) << "= passes: " << so_far.passes
           << "\n= spp: " << so_far.spp << "\n= seconds: ";
    header.precision(17);
    header << elapsed << "\n= size: " << accumulator.width() << "x"
           << rgba.size() / 4 / static_cast<size_t>(accumulator.width())
           << "\n= checksum: " << std::hex
           << sums_checksum(rgba.data(), rgba.size() * sizeof(float), luminance.data(),
                            luminance.size() * sizeof(double))
           << "\nend\n";
    const std::string tmp = m_path + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << header.str();
        out.write(reinterpret_cast<const char*>(rgba.data()),
                  static_cast<std::streamsize>(rgba.size() * sizeof(float)));
        out.write(reinterpret_cast<const char*>(luminance.data()),
                  static_cast<std::streamsize>(luminance.size() * sizeof(double)));
        out.flush();
        if (!out) {
            const int error = errno;
            std::remove(tmp.c_str());
            m_failure = "cannot keep the passes in '" + m_path + "' (" + std::strerror(error) + ")";
            return;
        }
    }
    if (std::rename(tmp.c_str(), m_path.c_str()) != 0) {
        const int error = errno;
        std::remove(tmp.c_str());
        m_failure = "cannot keep the passes in '" + m_path + "' (" + std::strerror(error) + ")";
        return;
    }
    m_kept.passes = so_far.passes;
    m_kept.spp = so_far.spp;
}

void PassJournal::remove() {
    std::remove(m_path.c_str());
}

}  // namespace rayo
