#pragma once
// The SPD's testing procedure (Eric Haines' Standard Procedural Databases, Readme.txt "Testing
// Procedures" and the ray counts under "Database Analysis"; docs/references.md#haines-1987)
// as `rayo bench suite --procedure spd` (docs/performance.md, "The SPD's testing procedure"): the
// render settings its rules ask for, the Readme's ray counts, and rayo's counts checked against
// them.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "apps/scene/scene_description.h"
#include "core/stats.h"

namespace rayo {

// The Readme's "Database Analysis" counts for one database at its default size: 513 × 513 eye
// rays, one per pixel corner.
struct SpdRayCounts {
    uint64_t eye_hit = 0, reflect = 0, refract = 0, shadow = 0;
};
const SpdRayCounts& spd_readme_counts(const std::string& scene);

// The Readme's figure for the counts: "should all be within about 10%".
constexpr double kSpdCountTolerance = 0.10;
// The procedure's image: 512 × 512 pixels, rays through the 513 × 513 corners (rule 6).
constexpr int kSpdProcedureWidth = 512;

// Sets the rules of the procedure on a scene's render settings: rays through the pixel corners,
// the four averaged, each corner traced once (rule 6: aa "corners"); the eye ray of depth 1 and
// at most depth 5 (rule 7: rayo counts the camera ray as depth 0, so max_depth 4); no adaptive
// tree depth cutoff (rule 8: min_contribution 0); a reflection ray at every hit on a reflecting
// or transmitting surface, unless at the maximum depth (rules 8 and 9: reflect_at_transmitters,
// since the SPD's glass gears have Ks 0). Rule 10, no shadow ray toward a light the surface
// normal faces away from, is rayo's own rule already; opaque shadows (no filtered ones).
void apply_spd_procedure(RenderSettings& settings);

// One count of one scene against the Readme: rayo's count scaled to 513² eye rays (the image's
// (W + 1)² corners otherwise), and the relative difference.
struct SpdCountCheck {
    std::string scene, kind;  // kind: "eye hit", "reflect", "refract", "shadow"
    double rayo = 0;          // scaled to 513² eye rays
    uint64_t readme = 0;
    double off = 0;  // (rayo − readme) / readme; 0 when both are 0, infinite when readme is 0
    bool within() const { return std::abs(off) <= kSpdCountTolerance; }
};

// The four counts of a scene rendered at `width` with the procedure's settings.
std::vector<SpdCountCheck> check_spd_counts(const std::string& scene, const RayCounters& rays,
                                            int width);

}  // namespace rayo
