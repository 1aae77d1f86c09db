#pragma once
// Every file a scene brings in (the scene itself, meshes, material libraries, glTF buffers) is
// opened here: only regular files (a directory, FIFO, device or socket is refused by name before
// it is opened for reading, so /dev/zero cannot fill memory and a FIFO cannot block), with the
// size checked against a per-kind limit before reading, and, for scenes from untrusted sources,
// confined to the scene's directory tree (docs/limits.md, "Trust model").
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rayo {

// Size limits checked before a file is read (docs/limits.md); far above real files (the largest
// SPD databases at size factor 10 are a few hundred MB).
constexpr uint64_t kMaxSceneFileBytes = uint64_t(1) << 31;     // NFF and JSON scenes: 2 GiB
constexpr uint64_t kMaxMeshFileBytes = uint64_t(1) << 31;      // OBJ, glTF, .bin buffers: 2 GiB
constexpr uint64_t kMaxMaterialFileBytes = uint64_t(1) << 26;  // .mtl libraries: 64 MiB
constexpr uint64_t kMaxVoxelFileBytes = uint64_t(1) << 30;     // raw voxel files: 1 GiB

// A file a scene read, as it was then: the resume fingerprint covers these (a texture replaced
// between an interrupted render and its --resume gave an image half old, half new).
struct InputFileRecord {
    std::string path;
    uint64_t bytes = 0;
    int64_t modified_ns = 0;  // st_mtim, nanoseconds since the epoch
};

// Which files a scene may reference. By default any readable regular file (relative names
// resolve against the scene's directory; ".." and absolute paths are allowed, as users expect).
// Confined: every referenced file, after following symbolic links, must lie inside the scene
// file's directory tree (`--restrict-paths`).
class FileAccess {
  public:
    FileAccess() = default;
    // Confined to the directory of `scene_path` (resolved with realpath).
    static FileAccess confined_to_scene(const std::string& scene_path);

    bool confined() const { return !m_root.empty(); }
    const std::string& root() const { return m_root; }

    // Throws InputError(where, ...) when access is confined and `path` resolves outside the
    // root. A path that does not exist is left to the open that follows (its own message).
    void check(const std::string& path, const std::string& where) const;

    // From now on, every file read_input_file reads through this access (or a copy of it) is
    // recorded, once per path, in the order read.
    void keep_log();
    void record(const std::string& path, uint64_t bytes, int64_t modified_ns) const;
    std::vector<InputFileRecord> log() const;

  private:
    std::string m_root;  // canonical directory, no trailing slash; empty: not confined
    std::shared_ptr<std::vector<InputFileRecord>> m_log;  // shared by copies; null: no log
};

// Checks that `path` names a regular file no larger than `max_bytes` (following symbolic
// links) that `access` allows, without reading it. `what` names the kind in messages ("scene
// file", "mesh file", ...). Throws InputError(where, "<what> '<path>' ...: <reason>").
void require_input_file(const std::string& path, const std::string& where, const std::string& what,
                        uint64_t max_bytes, const FileAccess& access = {});

// The whole file, after the checks of require_input_file; the read is bounded by `max_bytes`
// even if the file grows meanwhile.
std::string read_input_file(const std::string& path, const std::string& where,
                            const std::string& what, uint64_t max_bytes,
                            const FileAccess& access = {});

}  // namespace rayo
