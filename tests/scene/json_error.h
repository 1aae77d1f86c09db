#pragma once
// The error a JSON scene text is refused with (InputError::what(): "s.json#/pointer: message"),
// or "no error": what the scene tests' bad-input cases compare against.
#include <string>

#include "apps/scene/json_loader.h"
#include "core/error.h"

namespace rayo {

inline std::string json_error_of(const std::string& text, const std::string& name = "s.json",
                                 const std::string& dir = ".") {
    try {
        load_json_string(text, name, dir);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace rayo
