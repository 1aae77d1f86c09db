// libFuzzer target for the OBJ import path (apps/scene/mesh_loader.cpp load_obj, tinyobjloader):
// the input is written as an .obj next to tri.mtl (fuzz/fuzz_files.h), loaded, and then put through
// what the JSON loader does with a mesh (transform, degenerate-triangle removal, normals).
// An accepted mesh must pass the mesh invariants; a refusal must be rayo::InputError.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "apps/scene/mesh_loader.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/scene_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = rayo::fuzz::write_input("fuzz.obj", data, size);
    std::vector<rayo::Material> materials(1);
    try {
        rayo::TriangleMesh mesh = rayo::load_obj(path, materials, "fuzz.json#/objects/0/file");
        rayo::fuzz::check_mesh(mesh, materials.size(), "obj mesh (as loaded)");
        rayo::drop_degenerate_triangles(mesh);
        rayo::compute_vertex_normals(mesh);
        rayo::fuzz::check_mesh(mesh, materials.size(), "obj mesh (after normals)");
    } catch (const rayo::InputError&) {
    }
    return 0;
}
