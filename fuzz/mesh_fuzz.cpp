// libFuzzer target for rayo's readers of PLY, STL and OFF (apps/scene/polygon_file_loader.h
// load_polygon_file: apps/scene/ply_reader.h, stl_reader.h, off_reader.h) and the triangulation
// of their faces. One fuzzer covers the three formats: the
// extension is picked from the content, as a user's file would be named: "ply" at the start is a
// .ply, "solid" an ASCII .stl, "OFF" (COFF, NOFF, ...) in its first token an .off, anything else a
// binary .stl (whose 80-byte header is free text). The mesh is then put through what the JSON
// loader does with one (degenerate-triangle removal, normals). An accepted mesh must pass the
// mesh invariants (fuzz/scene_invariants.h); a refusal must be rayo::InputError.
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "apps/scene/mesh_loader.h"
#include "apps/scene/polygon_file_loader.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/scene_invariants.h"

namespace {

// Whether the first token of `data` (after blanks) contains "OFF", as the OFF reader looks for it.
bool looks_like_off(const uint8_t* data, size_t size) {
    size_t at = 0;
    while (at < size && std::isspace(data[at])) ++at;
    std::string token;
    while (at < size && token.size() < 8 && !std::isspace(data[at])) token += char(data[at++]);
    for (char& c : token) c = char(std::toupper(static_cast<unsigned char>(c)));
    return token.find("OFF") != std::string::npos;
}

const char* extension_of(const uint8_t* data, size_t size) {
    if (size >= 3 && std::memcmp(data, "ply", 3) == 0) return ".ply";
    if (size >= 5 && std::memcmp(data, "solid", 5) == 0) return ".stl";
    if (looks_like_off(data, size)) return ".off";
    return ".stl";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path =
        rayo::fuzz::write_input(std::string("fuzz") + extension_of(data, size), data, size);
    std::vector<rayo::Material> materials(1);
    try {
        rayo::MeshImportStats stats;
        rayo::TriangleMesh mesh =
            rayo::load_polygon_file(path, materials, "fuzz.json#/objects/0/file", &stats);
        rayo::fuzz::expect(!mesh.triangles.empty(), "polygon file accepted without triangles");
        rayo::fuzz::check_mesh(mesh, materials.size(), "polygon file (as loaded)");
        rayo::drop_degenerate_triangles(mesh);
        rayo::compute_vertex_normals(mesh);
        rayo::fuzz::check_mesh(mesh, materials.size(), "polygon file (after normals)");
    } catch (const rayo::InputError&) {
    }
    return 0;
}
