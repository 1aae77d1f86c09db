#pragma once
// How spheres reach the intersection hot path, selectable per render for the analytic-vs-BVH
// comparison: every method renders the same scene; names are the CLI's (`--sphere-method`,
// `--sphere-math`).
#include <optional>
#include <string>

#include "core/setting.h"
#include "core/shapes/sphere.h"

namespace rayo {

enum class SphereMethod {
    BruteForce,   // every ray tests every sphere with our quadratic, no BVH (the reference)
    User,         // Embree user geometry running our quadratic (the design card's path)
    EmbreePoint,  // Embree's built-in RTC_GEOMETRY_TYPE_SPHERE_POINT
    Mesh,         // each sphere tessellated into an icosphere of Embree triangles
    Auto,         // chosen per scene (apps/scene/sphere_method_choice.h); never reaches Accel
};

struct SphereRepresentation {
    SphereMethod method = SphereMethod::User;
    int mesh_level = 3;       // icosphere subdivisions: 20·4^level triangles per sphere
    bool mesh_smooth = true;  // interpolated vertex normals (true) or flat facets
};

constexpr int kMaxMeshLevel = 7;  // 327,680 triangles per sphere

// Triangles per sphere for a tessellation level (icosahedron, each level splits a face in 4).
inline long long icosphere_triangles(int level) {
    return 20LL << (2 * level);
}

// "bruteforce", "user", "embree-point", "mesh:N" (N in 0..kMaxMeshLevel), "auto"; nullopt if
// the text is none of these.
std::optional<SphereRepresentation> parse_sphere_method(const std::string& text);
// What a sphere method is, as --help and the messages say it: one of "auto", "user",
// "bruteforce", "embree-point", "mesh:N" (N in 0..7).
std::string sphere_method_expectation();
// The check of --sphere-method and of "render": {"sphere_method"} (core/setting.h's form, one
// reader for both): sets `out` (its mesh_smooth kept), or says what was expected.
std::optional<std::string> read_sphere_method(const SettingValue& value, SphereRepresentation& out);
std::string sphere_method_name(const SphereRepresentation& r);

// "seed", "stable", "double".
std::optional<SphereMath> parse_sphere_math(const std::string& text);
const char* sphere_math_name(SphereMath math);

}  // namespace rayo
