#pragma once
// The integrator registry, the way core/shapes/primitives.h registers shapes: an integrator is
// a settings type (its scene-file name kName, a one-line kSummary, its fields() read by the
// scene reader and the command line alike, core/setting.h, and `using Integrator = ...`) and the
// integrator class it builds, constructed from an IntegratorContext and called by the tile loop
// (core/render.h). render_scene dispatches once per render (std::visit into the templated tile
// loop), never per ray. Adding one is its file pair and its entry in IntegratorSettings
// (docs/architecture.md, "Adding an integrator").
#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "shading/integrators/ambient_occlusion.h"
#include "shading/integrators/path.h"
#include "shading/integrators/whitted.h"

namespace rayo {

// Whitted first: the default.
using IntegratorSettings =
    std::variant<WhittedSettings, AmbientOcclusionSettings, PathSettings>;

template <typename F, size_t... I>
void for_each_integrator(F&& f, std::index_sequence<I...>) {
    (f(std::variant_alternative_t<I, IntegratorSettings>{}), ...);
}
// Calls f(S{}) for each registered settings type S, in order.
template <typename F>
void for_each_integrator(F&& f) {
    for_each_integrator(f, std::make_index_sequence<std::variant_size_v<IntegratorSettings>>{});
}

// The defaults of the integrator named `name`, or nothing.
inline std::optional<IntegratorSettings> integrator_named(const std::string& name) {
    std::optional<IntegratorSettings> found;
    for_each_integrator([&](auto s) {
        if (name == decltype(s)::kName) found = s;
    });
    return found;
}

inline const char* integrator_name(const IntegratorSettings& s) {
    return std::visit([](const auto& i) { return std::decay_t<decltype(i)>::kName; }, s);
}

// "one of "whitted", "ambient_occlusion"" (for errors and help).
inline std::string integrator_names() {
    std::string names;
    for_each_integrator([&](auto s) {
        names += std::string(names.empty() ? "" : ", ") + "\"" + decltype(s)::kName + "\"";
    });
    return names;
}

}  // namespace rayo
