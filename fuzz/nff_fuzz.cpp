// libFuzzer target for the NFF reader (apps/scene/nff_loader.cpp): any bytes must either load into
// a scene that passes fuzz/scene_invariants.h or be refused with rayo::InputError. Any other
// exception escapes and aborts, which libFuzzer reports as a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "apps/scene/nff_loader.h"
#include "fuzz/scene_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        rayo::fuzz::check_scene(rayo::load_nff_string(text, "fuzz.nff"));
    } catch (const rayo::InputError&) {
    }
    return 0;
}
