#pragma once
// How a shape names its scene-file fields, so that loaders read every registered shape with one
// generic reader (apps/scene/json_loader.cpp) and a new shape needs no loader code: the scene
// vocabulary is the code vocabulary. A shape's `fields(f)` calls, for each field,
//   f(name, member, FieldKind)            // required
//   f.optional(name, member, FieldKind)   // optional; the member's current value is the default
// and its `problem()` reports what the fields cannot say alone (apex = base, min > max, ...).
// Lights (shading/light.h) use the same fields; a type with a `finish()` has it called after
// its fields are read (to derive members from them, e.g. a spot's cosines from its angles).
#include <optional>
#include <string>

namespace rayo {

enum class FieldKind {
    Point,        // Vec3, any finite coordinates
    Direction,    // Vec3, non-zero; normalized when read
    Number,       // float
    Positive,     // float > 0
    NonNegative,  // float >= 0
    Integer,      // int
    Flag,         // bool
    Numbers,      // std::array<double, N>: exactly N finite numbers, kept in double
    Box,          // Bounds3: an object {"min": [x, y, z], "max": [x, y, z]}
    Records,      // std::vector<T>: an array of objects, each read by T's own fields()
    Colour,       // Vec3: [r, g, b] or one number (grey), each >= 0
    Attenuation,  // a light's distance attenuation object (shading/point_light.h)
};

// A constraint between fields that failed: the field to blame and what was expected.
struct FieldProblem {
    std::string field;
    std::string message;
};

}  // namespace rayo
