#include "bench/lab/spd_procedure.h"

#include <limits>
#include <map>

#include "core/error.h"

namespace rayo {

const SpdRayCounts& spd_readme_counts(const std::string& scene) {
    // The SPD's Readme.txt (version 3.14), "Database Analysis": eye hit, reflect, refract and
    // shadow rays of each database at its default size, 513 × 513 eye rays.
    static const std::map<std::string, SpdRayCounts> table = {
        {"balls", {263169, 175095, 0, 954368}},      {"gears", {245086, 304643, 207564, 2246955}},
        {"mount", {173125, 354769, 354769, 412922}}, {"rings", {263169, 315236, 0, 1085002}},
        {"teapot", {161120, 225248, 0, 407656}},     {"tetra", {49788, 0, 0, 46112}},
        {"tree", {169836, 0, 0, 1097419}},
    };
    const auto it = table.find(scene);
    if (it == table.end()) throw InputError("spd:" + scene, "not one of the SPD's databases");
    return it->second;
}

void apply_spd_procedure(RenderSettings& settings) {
    settings.aa = AntiAliasing::Corners;
    settings.spp = 1;
    settings.integrator = WhittedSettings{};
    WhittedSettings& whitted = settings.whitted();
    whitted.max_depth = 4;
    whitted.min_contribution = 0.0f;
    whitted.reflect_at_transmitters = true;
    whitted.shadows = ShadowMode::Opaque;
}

std::vector<SpdCountCheck> check_spd_counts(const std::string& scene, const RayCounters& rays,
                                            int width) {
    const SpdRayCounts& readme = spd_readme_counts(scene);
    // The Readme's counts are for 513² eye rays; an image of W² pixels has (W + 1)² corners.
    const double corners = double(kSpdProcedureWidth + 1) / double(width + 1);
    const double scale = corners * corners;
    std::vector<SpdCountCheck> checks;
    const auto add = [&](const char* kind, uint64_t count, uint64_t expected) {
        SpdCountCheck c;
        c.scene = scene;
        c.kind = kind;
        c.rayo = double(count) * scale;
        c.readme = expected;
        c.off = expected > 0 ? (c.rayo - double(expected)) / double(expected)
                : count == 0 ? 0.0
                             : std::numeric_limits<double>::infinity();
        checks.push_back(c);
    };
    add("eye hit", rays.camera_hits, readme.eye_hit);
    add("reflect", rays.reflection, readme.reflect);
    add("refract", rays.refraction, readme.refract);
    add("shadow", rays.shadow + rays.shadow_filtered, readme.shadow);
    return checks;
}

}  // namespace rayo
