// libFuzzer target for the glTF import path (apps/scene/mesh_loader.cpp load_gltf, tinygltf):
// inputs that start with the binary magic "glTF" are written as .glb, others as .gltf, next to
// tri.bin (fuzz/fuzz_files.h) for external-buffer references. An accepted mesh must pass the mesh
// invariants; a refusal must be rayo::InputError.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "apps/scene/mesh_loader.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/scene_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::string path = rayo::fuzz::write_input(binary ? "fuzz.glb" : "fuzz.gltf", data, size);
    std::vector<rayo::Material> materials(1);
    try {
        rayo::TriangleMesh mesh = rayo::load_gltf(path, materials, "fuzz.json#/objects/0/file");
        rayo::fuzz::check_mesh(mesh, materials.size(), "gltf mesh (as loaded)");
        rayo::drop_degenerate_triangles(mesh);
        rayo::compute_vertex_normals(mesh);
        rayo::fuzz::check_mesh(mesh, materials.size(), "gltf mesh (after normals)");
    } catch (const rayo::InputError&) {
    }
    return 0;
}
