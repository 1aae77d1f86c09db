#include "core/sphere_method.h"

#include <charconv>

namespace rayo {

std::optional<SphereRepresentation> parse_sphere_method(const std::string& text) {
    SphereRepresentation r;
    if (text == "bruteforce") {
        r.method = SphereMethod::BruteForce;
    } else if (text == "user") {
        r.method = SphereMethod::User;
    } else if (text == "embree-point") {
        r.method = SphereMethod::EmbreePoint;
    } else if (text == "auto") {
        r.method = SphereMethod::Auto;
    } else if (text.rfind("mesh:", 0) == 0) {
        const char* begin = text.data() + 5;
        const char* end = text.data() + text.size();
        int level = -1;
        const auto [ptr, ec] = std::from_chars(begin, end, level);
        if (ec != std::errc() || ptr != end || begin == end || level < 0 || level > kMaxMeshLevel) {
            return std::nullopt;
        }
        r.method = SphereMethod::Mesh;
        r.mesh_level = level;
    } else {
        return std::nullopt;
    }
    return r;
}

std::string sphere_method_name(const SphereRepresentation& r) {
    switch (r.method) {
        case SphereMethod::BruteForce:
            return "bruteforce";
        case SphereMethod::User:
            return "user";
        case SphereMethod::EmbreePoint:
            return "embree-point";
        case SphereMethod::Mesh:
            return "mesh:" + std::to_string(r.mesh_level);
        case SphereMethod::Auto:
            return "auto";
    }
    return "?";
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
