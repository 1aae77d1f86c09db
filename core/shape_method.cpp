#include "core/shape_method.h"

namespace rayo {

std::optional<ShapeMethod> parse_shape_method(const std::string& text) {
    if (text == "analytic") return ShapeMethod::Analytic;
    if (text == "mesh") return ShapeMethod::Mesh;
    if (text == "auto") return ShapeMethod::Auto;
    return std::nullopt;
}

const char* shape_method_name(ShapeMethod method) {
    switch (method) {
        case ShapeMethod::Analytic:
            return "analytic";
        case ShapeMethod::Mesh:
            return "mesh";
        case ShapeMethod::Auto:
            return "auto";
    }
    return "?";
}

}  // namespace rayo
