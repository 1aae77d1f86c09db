#pragma once
// Scratch files for the fuzzers: a private folder (in /dev/shm when there is one, so writing an
// input per run is cheap) holding the small meshes the seed corpora refer to by name
// (tri.obj + tri.mtl, tri.gltf + tri.bin), the height image dem.pgm and the voxel file vox.raw,
// and a helper that writes the current input there.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rayo::fuzz {

inline const char* const kTriObj =
    "mtllib tri.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nusemtl red\nf 1//1 2//1 3//1\n";
inline const char* const kTriMtl =
    "newmtl red\nKa 0.1 0 0\nKd 0.8 0.1 0.1\nKs 0.5 0.5 0.5\nNs 64\n";
inline const char* const kTriGltf = R"({
  "asset": {"version": "2.0"},
  "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"uri": "tri.bin", "byteLength": 44}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]
})";

// Little-endian bytes of tri.bin: three float vec3 positions, three u16 indices, two pad bytes.
inline std::string tri_bin() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const uint16_t indices[4] = {0, 1, 2, 0};
    std::string bytes(44, '\0');
    std::memcpy(&bytes[0], positions, sizeof positions);
    std::memcpy(&bytes[36], indices, sizeof indices);
    return bytes;
}

inline void write_file(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(bytes.data(), static_cast<long>(bytes.size()));
}

// The fuzzer's scratch folder, created (with the meshes) on first use.
inline const std::filesystem::path& scratch_dir() {
    static const std::filesystem::path dir = [] {
        const std::filesystem::path shm = "/dev/shm";
        const std::filesystem::path base =
            ::access(shm.c_str(), W_OK) == 0 ? shm : std::filesystem::temp_directory_path();
        const std::filesystem::path d = base / ("rayo_fuzz_" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        write_file(d / "tri.obj", kTriObj);
        write_file(d / "tri.mtl", kTriMtl);
        write_file(d / "tri.gltf", kTriGltf);
        write_file(d / "tri.bin", tri_bin());
        write_file(d / "dem.pgm",
                   std::string("P5 3 3 255\n\x00\x40\x80\x20\xff\x60\x10\x30\x50", 20));
        // 32 bytes: 4 × 4 × 2 u8 voxels, 4 × 2 × 2 u16 or 2 × 2 × 2 f32 (0, 0.25, ..., finite).
        write_file(d / "vox.raw",
                   std::string("\x00\x00\x00\x00\x00\x00\x80\x3e\x00\x00\x00\x3f\x00\x00\x40\x3f"
                               "\x00\x00\x80\x3f\x00\x00\x20\x3f\x00\x00\xc0\x3e\x00\x00\x60\x3f",
                               32));
        return d;
    }();
    // libFuzzer ends a clean run with exit(): remove the folder then (a crash keeps it). Registered
    // after `dir` is built, so the handler runs before `dir` is destroyed.
    static const bool cleanup_registered = [] {
        return std::atexit([] {
                   std::error_code ignored;
                   std::filesystem::remove_all(scratch_dir(), ignored);
               }) == 0;
    }();
    (void)cleanup_registered;
    return dir;
}

// Writes the input as `name` in the scratch folder and returns its path.
inline std::string write_input(const std::string& name, const uint8_t* data, size_t size) {
    const std::filesystem::path p = scratch_dir() / name;
    write_file(p, std::string(reinterpret_cast<const char*>(data), size));
    return p.string();
}

}  // namespace rayo::fuzz
