#include "core/shape_method.h"

namespace rayo {

std::optional<ShapeMethod> parse_shape_method(const std::string& text) {
    for (const Choice<ShapeMethod>& c : kShapeMethodChoices) {
        if (text == c.name) return c.value;
    }
    return std::nullopt;
}

const char* shape_method_name(ShapeMethod method) {
    return choice_name(kShapeMethodChoices, method);
}

}  // namespace rayo
