// libFuzzer target for the JSON scene reader (apps/scene/json_loader.cpp), mesh references
// included: relative mesh paths resolve in the scratch folder that holds tri.obj / tri.gltf
// (fuzz/fuzz_files.h). Loaded scenes must pass fuzz/scene_invariants.h; refusals must be
// rayo::InputError (any other exception escapes and aborts: a finding).
#include <cstddef>
#include <cstdint>
#include <string>

#include "apps/scene/json_loader.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/scene_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string base_dir = rayo::fuzz::scratch_dir().string();
    try {
        rayo::fuzz::check_scene(rayo::load_json_string(text, "fuzz.json", base_dir));
    } catch (const rayo::InputError&) {
    }
    return 0;
}
