#include "core/image/partial_render.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "core/error.h"

namespace rayo {

namespace {

constexpr const char* kMagicLine = "rayo partial render 1";
constexpr uint64_t kRecordMagic = 0x454c4954'4f594152ULL;  // "RAYOTILE", little-endian
// Tiles queued for the disk before workers wait: what a kill -9 can lose besides the tiles
// being rendered (64 float tiles of 64²).
constexpr size_t kQueueBytes = size_t(4) << 20;
// The longest a written tile waits for its fdatasync: what a power loss can lose besides the
// queue.
constexpr std::chrono::milliseconds kSyncInterval{1000};
constexpr size_t kHeaderAlign = 4096;
constexpr size_t kMaxHeaderBytes = size_t(1) << 20;

// The fixed header of a tile's record; the pixels follow.
struct RecordHeader {
    uint64_t magic = kRecordMagic;
    uint32_t index = 0;
    uint32_t pixels = 0;
    uint64_t pixel_checksum = 0;
    uint64_t header_checksum = 0;  // of the 24 bytes above

    uint64_t own_checksum() const { return checksum64(this, 24); }
};
static_assert(sizeof(RecordHeader) == 32, "records are 32 bytes of header and the pixels");

// Takes the advisory lock that says "a rayo render is writing this partial render now"
// (flock(2): held by the open file, so it ends with the process, kill -9 included). False when
// another process holds it.
bool lock_exclusively(int fd) {
    return ::flock(fd, LOCK_EX | LOCK_NB) == 0;
}

// Whether another process holds the lock of the partial render at `path` (a render of the
// same output running now).
bool locked_by_another_render(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool locked = ::flock(fd, LOCK_SH | LOCK_NB) != 0;  // shared: two probes never clash
    ::close(fd);
    return locked;
}

std::string running_now_message(const std::string& path) {
    return "another rayo render of this output is running now (its partial render '" + path +
           "' is locked); wait for it to end, or write to another output";
}

// All `bytes` at `offset` through pread or pwrite (retried after EINTR and short counts); false
// on an error or at the end of the file.
template <typename Io, typename Byte>
bool transfer_at(Io io, int fd, Byte* data, size_t bytes, size_t offset) {
    while (bytes > 0) {
        const ssize_t n = io(fd, data, bytes, static_cast<off_t>(offset));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        bytes -= static_cast<size_t>(n);
        offset += static_cast<size_t>(n);
    }
    return true;
}

bool read_at(int fd, void* data, size_t bytes, size_t offset) {
    return transfer_at(::pread, fd, static_cast<char*>(data), bytes, offset);
}

bool write_at(int fd, const void* data, size_t bytes, size_t offset) {
    return transfer_at(::pwrite, fd, static_cast<const char*>(data), bytes, offset);
}

}  // namespace

// "name: value" lines (a value's line breaks become spaces).
std::string fingerprint_text(const RenderFingerprint& fingerprint) {
    std::string text;
    for (const auto& [name, value] : fingerprint) {
        std::string line = value;
        for (char& c : line)
            if (c == '\n' || c == '\r' || c == '\0') c = ' ';
        text += name + ": " + line + "\n";
    }
    return text;
}

RenderFingerprint parse_fingerprint(const std::string& text) {
    RenderFingerprint entries;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        const size_t colon = line.find(": ");
        if (colon != std::string::npos)
            entries.emplace_back(line.substr(0, colon), line.substr(colon + 2));
    }
    return entries;
}

std::string fingerprint_differences(const RenderFingerprint& before, const RenderFingerprint& now,
                                    const std::string& kept) {
    std::string differences;
    auto value_in = [](const RenderFingerprint& f, const std::string& name) -> const std::string* {
        for (const auto& [key, value] : f)
            if (key == name) return &value;
        return nullptr;
    };
    for (const auto& [name, value] : now) {
        const std::string* old = value_in(before, name);
        if (old && *old == value) continue;
        differences += "\n  " + name + ": " + (old ? *old : "(not recorded)") + " in the " + kept +
                       ", " + value + " now";
    }
    for (const auto& [name, value] : before) {
        if (!value_in(now, name))
            differences += "\n  " + name + ": " + value + " in the " + kept + ", (none) now";
    }
    return differences;
}

std::string partial_render_path(const std::string& output) {
    return output + ".rayo-partial";
}

uint64_t checksum64(const void* data, size_t bytes) {
    uint64_t hash = 0xcbf29ce484222325ULL;
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i + 8 <= bytes; i += 8) {
        uint64_t word;
        std::memcpy(&word, p + i, 8);
        hash = (hash ^ word) * 0x100000001b3ULL;
    }
    return hash;
}

// Passes tiles on and records them; begin() replays the saved ones first.
class PartialRender::Recorder : public TileSink {
  public:
    Recorder(PartialRender& partial, TileSink& inner) : m_partial(partial), m_inner(inner) {}
    void begin(const TileGrid& grid) override {
        m_inner.begin(grid);
        m_partial.replay(m_inner);
    }
    void write_tile(const Tile& tile, const float* rgba) override {
        m_inner.write_tile(tile, rgba);
        m_partial.record(tile, rgba);
    }
    void finish() override {
        m_partial.flush();
        m_inner.finish();
        m_partial.m_complete = true;
    }

  private:
    PartialRender& m_partial;
    TileSink& m_inner;
};

PartialRender::PartialRender(const std::string& output, const TileGrid& grid,
                             const RenderFingerprint& fingerprint)
    : m_output(output),
      m_path(partial_render_path(output)),
      m_grid(grid),
      m_done(static_cast<size_t>(grid.tile_count()), 0) {
    const std::string body = fingerprint_text(fingerprint);
    // The first line gives the header's size, so that the slots can be found before the
    // fingerprint is parsed.
    const size_t text_bytes = std::strlen(kMagicLine) + 24 + body.size();
    m_header_bytes = (text_bytes + kHeaderAlign - 1) / kHeaderAlign * kHeaderAlign;
    m_header = std::string(kMagicLine) + " " + std::to_string(m_header_bytes) + "\n" + body;
    m_header.resize(m_header_bytes, '\0');
}

std::unique_ptr<PartialRender> PartialRender::create(
    const std::string& output, const TileGrid& grid, const RenderFingerprint& fingerprint,
    std::chrono::steady_clock::duration keep_after) {
    std::unique_ptr<PartialRender> partial(new PartialRender(output, grid, fingerprint));
    partial->m_keep_from = std::chrono::steady_clock::now() + keep_after;
    struct stat info {};
    // Something that is not a file of ours under the name (a symbolic link, dangling or not, a
    // directory, a FIFO): neither a render running now nor a partial render to resume.
    if (::lstat(partial->m_path.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
        throw InputError(output,
                         "'" + partial->m_path + "' exists and is " +
                             (S_ISLNK(info.st_mode) ? "a symbolic link" : "not a regular file") +
                             ", not a partial render rayo wrote: remove it, or write to "
                             "another output");
    }
    if (::stat(partial->m_path.c_str(), &info) == 0) {
        if (locked_by_another_render(partial->m_path))
            throw InputError(output, running_now_message(partial->m_path));
        throw InputError(output, "a partial render of this output exists ('" + partial->m_path +
                                     "'): continue it with --resume, or remove it to start over");
    }
    partial->m_thread = std::thread([p = partial.get()] { p->run(); });
    return partial;
}

std::unique_ptr<PartialRender> PartialRender::resume(const std::string& output,
                                                     const TileGrid& grid,
                                                     const RenderFingerprint& fingerprint) {
    std::unique_ptr<PartialRender> partial(new PartialRender(output, grid, fingerprint));
    PartialRender& p = *partial;
    p.m_fd = ::open(p.m_path.c_str(), O_RDWR | O_CLOEXEC);
    if (p.m_fd < 0) {
        const int error = errno;
        throw InputError(output, "--resume: cannot open the partial render '" + p.m_path +
                                     "': " + std::strerror(error) +
                                     (error == ENOENT ? " (nothing to resume)" : ""));
    }
    if (!lock_exclusively(p.m_fd)) {
        ::close(p.m_fd);
        p.m_fd = -1;
        throw InputError(output, "--resume: " + running_now_message(p.m_path));
    }
    // The header: its first line, then the fingerprint up to the padding.
    std::string first(kHeaderAlign, '\0');
    const ssize_t got = ::pread(p.m_fd, first.data(), first.size(), 0);
    const std::string magic = std::string(kMagicLine) + " ";
    size_t saved_bytes = 0;
    if (got > 0 && first.compare(0, magic.size(), magic) == 0)
        saved_bytes = std::strtoull(first.c_str() + magic.size(), nullptr, 10);
    if (saved_bytes > kMaxHeaderBytes) saved_bytes = 0;  // not one of ours: refused below
    std::string saved(saved_bytes, '\0');
    if (saved_bytes < kHeaderAlign || saved_bytes % kHeaderAlign != 0 ||
        !read_at(p.m_fd, saved.data(), saved.size(), 0)) {
        ::close(p.m_fd);
        p.m_fd = -1;
        throw InputError(output, "--resume: '" + p.m_path + "' is not a partial render of rayo");
    }
    saved.resize(std::strlen(saved.c_str()));
    const RenderFingerprint before = parse_fingerprint(saved.substr(saved.find('\n') + 1));
    const std::string differences = fingerprint_differences(before, fingerprint, "partial render");
    if (!differences.empty()) {
        ::close(p.m_fd);
        p.m_fd = -1;
        throw InputError(output, "--resume: the partial render '" + p.m_path +
                                     "' was made with other settings:" + differences +
                                     "\nresume with the same scene and settings, or remove it "
                                     "to start over");
    }
    p.m_header = saved;
    p.m_header.resize(saved_bytes, '\0');
    p.m_header_bytes = saved_bytes;
    p.scan();
    p.m_existing = true;  // from here on, the destructor removes it if it holds no tile
    p.m_thread = std::thread([q = partial.get()] { q->run(); });
    return partial;
}

PartialRender::~PartialRender() {
    {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
    // Unlinked before it is closed, so that no other render can take the lock of a file that
    // is about to go.
    if (m_done_count == 0 && (m_fd >= 0 || m_existing)) ::unlink(m_path.c_str());
    if (m_fd >= 0) ::close(m_fd);
}

size_t PartialRender::slot_bytes() const {
    const size_t side = static_cast<size_t>(m_grid.tile_size());
    return sizeof(RecordHeader) + side * side * 4 * sizeof(float);
}

size_t PartialRender::slot_offset(int index) const {
    return m_header_bytes + static_cast<size_t>(index) * slot_bytes();
}

void PartialRender::fail(const std::string& what, int error) const {
    throw InputError(m_output,
                     "partial render '" + m_path + "': " + what + ": " + std::strerror(error));
}

// Reads every slot; a record counts when its header and pixels match their checksums.
void PartialRender::scan() {
    std::vector<float> pixels;
    for (int index = 0; index < m_grid.tile_count(); ++index) {
        const Tile tile = m_grid.tile(index);
        RecordHeader header;
        if (!read_at(m_fd, &header, sizeof header, slot_offset(index))) continue;
        if (header.magic != kRecordMagic || header.index != static_cast<uint32_t>(index) ||
            header.pixels != tile.pixel_count() || header.header_checksum != header.own_checksum())
            continue;
        pixels.resize(tile.pixel_count() * 4);
        const size_t bytes = pixels.size() * sizeof(float);
        if (!read_at(m_fd, pixels.data(), bytes, slot_offset(index) + sizeof header)) continue;
        if (checksum64(pixels.data(), bytes) != header.pixel_checksum) continue;
        m_done[index] = 1;
        ++m_done_count;
    }
}

void PartialRender::replay(TileSink& inner) const {
    std::vector<float> pixels;
    for (int index = 0; index < m_grid.tile_count(); ++index) {
        if (!m_done[index]) continue;
        const Tile tile = m_grid.tile(index);
        pixels.resize(tile.pixel_count() * 4);
        if (!read_at(m_fd, pixels.data(), pixels.size() * sizeof(float),
                     slot_offset(index) + sizeof(RecordHeader)))
            fail("cannot read tile " + std::to_string(index), errno != 0 ? errno : EIO);
        inner.write_tile(tile, pixels.data());
    }
}

int PartialRender::tiles_done() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_done_count;
}

std::vector<int> PartialRender::missing_tiles() const {
    std::vector<int> missing;
    std::lock_guard<std::mutex> lock(m_mutex);
    for (int index = 0; index < m_grid.tile_count(); ++index)
        if (!m_done[index]) missing.push_back(index);
    return missing;
}

std::string PartialRender::failure() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_error;
}

std::unique_ptr<TileSink> PartialRender::recording_sink(TileSink& inner) {
    return std::make_unique<Recorder>(*this, inner);
}

void PartialRender::raise_after(int tiles, int signal_number) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_raise_after = tiles;
    m_raise_signal = signal_number;
}

void PartialRender::record(const Tile& tile, const float* rgba) {
    const size_t bytes = tile.pixel_count() * 4 * sizeof(float);
    const bool keep = std::chrono::steady_clock::now() >= m_keep_from;
    std::unique_lock<std::mutex> lock(m_mutex);
    if (keep) {
        m_idle.wait(lock, [&] {
            return !m_error.empty() || m_jobs.empty() || m_queued_bytes + bytes <= kQueueBytes;
        });
        // After a failure the partial render stops growing (failure()).
        if (m_error.empty()) {
            m_jobs.push_back({tile, std::vector<float>(rgba, rgba + tile.pixel_count() * 4)});
            m_queued_bytes += bytes;
            m_wake.notify_one();
        }
    }
    if (m_raise_after > 0 && ++m_finished_this_run == m_raise_after) {
        lock.unlock();
        std::raise(m_raise_signal);  // on this worker: it takes no further tile
    }
}

void PartialRender::flush() {
    std::unique_lock<std::mutex> lock(m_mutex);
    m_sync_requested = true;
    m_wake.notify_all();
    m_idle.wait(lock, [&] {
        return !m_error.empty() || (m_jobs.empty() && !m_writing && m_unsynced.empty());
    });
    m_sync_requested = false;
}

void PartialRender::remove() {
    flush();
    ::unlink(m_path.c_str());  // before the close, as in the destructor
    if (m_fd >= 0) ::close(m_fd);
    m_fd = -1;
    std::lock_guard<std::mutex> lock(m_mutex);
    m_done_count = 0;
    m_existing = false;
}

// Creates the file (its header first, on the disk before any tile).
void PartialRender::open_for_writing() {
    if (m_fd >= 0) return;
    m_fd = ::open(m_path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (m_fd < 0 && errno == EEXIST) throw InputError(m_output, running_now_message(m_path));
    if (m_fd < 0) fail("cannot create", errno);
    lock_exclusively(m_fd);  // a new file: nobody else can hold its lock
    if (!write_at(m_fd, m_header.data(), m_header.size(), 0)) fail("cannot write", errno);
}

// One batch: every record written (pwrite: in the page cache, safe from a killed process).
void PartialRender::write_batch(const std::deque<Job>& batch) {
    open_for_writing();
    for (const Job& job : batch) {
        RecordHeader header;
        header.index = static_cast<uint32_t>(job.tile.index);
        header.pixels = static_cast<uint32_t>(job.tile.pixel_count());
        const size_t bytes = job.rgba.size() * sizeof(float);
        header.pixel_checksum = checksum64(job.rgba.data(), bytes);
        header.header_checksum = header.own_checksum();
        const size_t offset = slot_offset(job.tile.index);
        if (!write_at(m_fd, &header, sizeof header, offset) ||
            !write_at(m_fd, job.rgba.data(), bytes, offset + sizeof header))
            fail("cannot write", errno);
    }
}

// The writer thread: writes each batch as it comes and makes the written tiles durable with one
// fdatasync at most every kSyncInterval, or at once when flush() or the destructor asks; a tile
// counts as done only after that. (One fdatasync per batch cost 0.15 s of a 2.4 s render at
// 2048², docs/performance.md "Fixed costs".)
void PartialRender::run() {
    using Clock = std::chrono::steady_clock;
    Clock::time_point last_sync = Clock::now();
    std::unique_lock<std::mutex> lock(m_mutex);
    // A sync was asked for (flush, close) or the interval has passed.
    const auto sync_due = [&] {
        return m_stop || m_sync_requested || Clock::now() - last_sync >= kSyncInterval;
    };
    const auto ready = [&] {
        return m_stop || !m_jobs.empty() || (!m_unsynced.empty() && sync_due());
    };
    for (;;) {
        if (m_unsynced.empty()) {
            m_wake.wait(lock, ready);
        } else {
            m_wake.wait_until(lock, last_sync + kSyncInterval, ready);
        }
        if (m_stop && m_jobs.empty() && m_unsynced.empty()) return;
        std::deque<Job> batch;
        batch.swap(m_jobs);
        // Only this thread changes m_unsynced: the tiles written before this batch.
        const bool sync = (!m_unsynced.empty() || !batch.empty()) && sync_due();
        const bool failed = !m_error.empty();
        m_writing = true;
        lock.unlock();
        std::string error;
        if (!failed) {
            try {
                if (!batch.empty()) write_batch(batch);
                if (sync && ::fdatasync(m_fd) != 0) fail("cannot write", errno);
            } catch (const std::exception& e) {
                error = e.what();
            }
        }
        if (sync) last_sync = Clock::now();
        lock.lock();
        for (const Job& job : batch) {
            m_queued_bytes -= job.rgba.size() * sizeof(float);
            if (!failed) m_unsynced.push_back(job.tile.index);
        }
        if (!error.empty()) m_error = error;
        if (!m_error.empty()) {
            m_unsynced.clear();  // the tiles on the disk before the failure stay done
        } else if (sync) {
            for (const int index : m_unsynced) {
                if (m_done[index]) continue;
                m_done[index] = 1;
                ++m_done_count;
            }
            m_unsynced.clear();
        }
        m_writing = false;
        m_idle.notify_all();
    }
}

}  // namespace rayo
