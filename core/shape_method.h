#pragma once
// How an analytic shape with a mesh form (its pieces(), core/shapes/tessellation.h) reaches the
// intersection hot path: its own analytic code as Embree user geometry, or a tessellation into
// Embree triangles within a chord-error budget; `auto` picks per object from the pixel error
// budget and measured costs (apps/scene/shape_method_choice.h, docs/shape-methods.md). Spheres
// have their own `--sphere-method` (core/sphere_method.h).
#include <cstdint>
#include <optional>
#include <string>

#include "core/setting.h"

namespace rayo {

enum class ShapeMethod {
    Analytic,  // Embree user geometry running the shape's intersection (the default)
    Mesh,      // Embree triangles within the chord error `--max-error-px` projects to
    Auto,      // chosen per object (apps/scene/shape_method_choice.h); never reaches Accel
};

// The methods by name, declared once: --shape-method and an object's "method" both read them
// (read_choice, core/setting.h), and --help lists them from here.
inline const std::initializer_list<Choice<ShapeMethod>> kShapeMethodChoices = {
    {"analytic", ShapeMethod::Analytic}, {"mesh", ShapeMethod::Mesh}, {"auto", ShapeMethod::Auto}};

// "analytic", "mesh", "auto"; nullopt if the text is none of these.
std::optional<ShapeMethod> parse_shape_method(const std::string& text);
const char* shape_method_name(ShapeMethod method);

// A scene file's "method" of one top-level object: the object is Scene::shapes' `index`-th of
// the type whose registry index is `type` (Shapes::index_of<S>()).
struct ShapeMethodRequest {
    uint32_t type = 0;
    uint32_t index = 0;
    ShapeMethod method = ShapeMethod::Analytic;
};

}  // namespace rayo
