#include "core/sphere_method.h"

#include <charconv>

namespace rayo {

namespace {

// The methods named by a word alone; "mesh:N" adds the tessellation level.
const std::initializer_list<Choice<SphereMethod>> kNamedMethods = {
    {"auto", SphereMethod::Auto},
    {"user", SphereMethod::User},
    {"bruteforce", SphereMethod::BruteForce},
    {"embree-point", SphereMethod::EmbreePoint}};
constexpr char kMeshPrefix[] = "mesh:";

}  // namespace

std::optional<SphereRepresentation> parse_sphere_method(const std::string& text) {
    SphereRepresentation r;
    for (const Choice<SphereMethod>& c : kNamedMethods) {
        if (text == c.name) {
            r.method = c.value;
            return r;
        }
    }
    if (text.rfind(kMeshPrefix, 0) != 0) return std::nullopt;
    const char* begin = text.data() + sizeof kMeshPrefix - 1;
    const char* end = text.data() + text.size();
    int level = -1;
    const auto [ptr, ec] = std::from_chars(begin, end, level);
    if (ec != std::errc() || ptr != end || begin == end || level < 0 || level > kMaxMeshLevel) {
        return std::nullopt;
    }
    r.method = SphereMethod::Mesh;
    r.mesh_level = level;
    return r;
}

std::string sphere_method_expectation() {
    std::string text = "one of ";
    for (const Choice<SphereMethod>& c : kNamedMethods) text += "\"" + std::string(c.name) + "\", ";
    return text + "\"" + kMeshPrefix + "N\" (N in 0.." + std::to_string(kMaxMeshLevel) + ")";
}

std::optional<std::string> read_sphere_method(const SettingValue& value,
                                              SphereRepresentation& out) {
    if (value.type == SettingValue::Type::Text) {
        if (const std::optional<SphereRepresentation> method = parse_sphere_method(value.text)) {
            const bool smooth = out.mesh_smooth;
            out = *method;
            out.mesh_smooth = smooth;
            return std::nullopt;
        }
    }
    return "expected " + sphere_method_expectation() + ", got " + value.shown;
}

std::string sphere_method_name(const SphereRepresentation& r) {
    if (r.method == SphereMethod::Mesh) return kMeshPrefix + std::to_string(r.mesh_level);
    return choice_name(kNamedMethods, r.method);
}

std::optional<SphereMath> parse_sphere_math(const std::string& text) {
    if (text == "seed") return SphereMath::Seed;
    if (text == "stable") return SphereMath::Stable;
    if (text == "double") return SphereMath::Double;
    return std::nullopt;
}

const char* sphere_math_name(SphereMath math) {
    switch (math) {
        case SphereMath::Seed:
            return "seed";
        case SphereMath::Stable:
            return "stable";
        case SphereMath::Double:
            return "double";
    }
    return "?";
}

}  // namespace rayo
