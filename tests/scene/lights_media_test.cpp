// Tests of the surface models, media and area lights through the JSON reader and the Whitted
// integrator, against closed forms: Fresnel reflectance at normal incidence, diffuse
// transmission, fog at a known distance, Beer–Lambert over a known chord, filtered shadows as
// the product of transmit colours, the irradiance and penumbra of a disk light, emitters seen by
// rays; and the determinism promise with every feature on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/accel.h"
#include "shading/integrators/whitted.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec3;
using rayo_test::same_bits;

SceneDescription load(const std::string& text) {
    return load_json_string(text, "scene.json", "");
}

// The radiance along one ray through the scene of `text`, traced by the Whitted integrator.
struct Tracer {
    explicit Tracer(const std::string& text)
        : description(load(text)),
          accel(description.scene, options()),
          integrator(accel, description.shading, description.settings.whitted()) {}
    static AccelOptions options() {
        AccelOptions o;
        o.spheres = SphereRepresentation{SphereMethod::User};
        return o;
    }
    Vec3 radiance(const Vec3& origin, const Vec3& direction) {
        Ray ray;
        ray.origin = origin;
        ray.direction = glm::normalize(direction);
        return integrator.radiance(ray, counters);
    }
    SceneDescription description;
    Accel accel;
    WhittedIntegrator integrator;
    RayCounters counters;
};

// ---- Surface models ---------------------------------------------------------------------------

TEST(FresnelMaterial, NormalIncidenceReflectsFourPercentOfTheBackground) {
    // An opaque Fresnel mirror of n = 1.5 seen head on reflects F(0) = 0.04 of the background
    // behind the camera; with "fresnel" off the constant reflect = 1 mirrors all of it.
    const std::string scene = R"({"rayo": 1, "background": [1, 0.5, 0.25],
      "materials": {"default": {"ka": 0, "kd": 0, "ior": 1.5, "fresnel": FRESNEL}},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})";
    auto with = [&](const char* fresnel) {
        std::string text = scene;
        text.replace(text.find("FRESNEL"), 7, fresnel);
        return text;
    };
    Tracer fresnel(with("true"));
    expect_vec3(fresnel.radiance(Vec3(0, 0, 5), Vec3(0, 0, -1)), 0.04, 0.02, 0.01, 1e-6);
    Tracer constant(with("false, \"reflect\": 1"));
    expect_vec3(constant.radiance(Vec3(0, 0, 5), Vec3(0, 0, -1)), 1.0, 0.5, 0.25, 0.0);
}

TEST(FresnelMaterial, GlassSplitsReflectAndTransmitByFresnel) {
    // A Fresnel glass slab (a box, n = 1.5, transmit 1): head on, 4% reflects (the background
    // in front is black) and 96% enters; at the back face 96% of that leaves toward the white
    // background behind: 0.96², plus the light bouncing inside (0.04² of it per round trip).
    Tracer t(R"({"rayo": 1, "background": 0,
      "materials": {"default": {"ka": 0, "kd": 0, "ior": 1.5, "transmit": 1, "fresnel": true},
                    "white": {"ka": 1, "kd": 0}},
      "render": {"max_depth": 12, "min_contribution": 0},
      "objects": [{"type": "box", "min": [-1, -1, -0.5], "max": [1, 1, 0.5]},
                  {"type": "disk", "center": [0, 0, -3], "normal": [0, 0, 1], "radius": 10,
                   "material": "white"}]})");
    // Through the slab: T² Σ R^(2k) = 0.96²/(1 − 0.04²).
    const double expected = 0.96 * 0.96 / (1.0 - 0.04 * 0.04);
    expect_vec3(t.radiance(Vec3(0, 0, 5), Vec3(0, 0, -1)), expected, expected, expected, 1e-5);
}

TEST(Translucency, LightBehindAThinSurfaceShinesThroughByItsCosine) {
    // A disk facing the camera (+z), a point light behind it (−z) at 60° off its axis: seed
    // 001's perfect diffuse transmission gives translucency·I·cos 60°; kd gives nothing.
    const std::string scene = R"({"rayo": 1,
      "materials": {"default": {"ka": 0, "kd": 0.9, "translucency": [0.5, 0.25, 1]}},
      "lights": [{"type": "point", "position": [X, 0, -1], "intensity": 2}],
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 5}]})";
    std::string text = scene;
    text.replace(text.find("X"), 1, std::to_string(std::sqrt(3.0)));
    Tracer t(text);
    const double c = 2.0 * 0.5;  // I·cos 60°
    expect_vec3(t.radiance(Vec3(0, 0, 5), Vec3(0, 0, -1)), 0.5 * c, 0.25 * c, 1.0 * c, 1e-5);
    // Without translucency the same light, behind the surface, gives nothing.
    const std::string translucency = R"(, "translucency": [0.5, 0.25, 1])";
    std::string opaque = text;
    opaque.replace(opaque.find(translucency), translucency.size(), "");
    Tracer o(opaque);
    expect_vec3(o.radiance(Vec3(0, 0, 5), Vec3(0, 0, -1)), 0.0, 0.0, 0.0, 0.0);
}

// ---- Media ------------------------------------------------------------------------------------

TEST(Fog, BlendsTowardItsColourByExpOfMinusDensityTimesDistance) {
    // A sphere of radiance 1 (ka = 1, Ia = 1) at distance 9: L·e^(−9σ) + C·(1 − e^(−9σ)).
    Tracer t(R"({"rayo": 1, "background": [0, 0, 1], "fog": {"color": [0.8, 0.6, 0.4],
      "density": 0.1}, "materials": {"default": {"ka": 1, "kd": 0}},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})");
    const double e = std::exp(-0.9);
    expect_vec3(t.radiance(Vec3(0, 0, 10), Vec3(0, 0, -1)), e + 0.8 * (1 - e), e + 0.6 * (1 - e),
                e + 0.4 * (1 - e), 1e-6);
    // A miss sees the pure fog colour, not the background.
    expect_vec3(t.radiance(Vec3(0, 0, 10), Vec3(0, 1, 0)), 0.8, 0.6, 0.4, 1e-7);
}

TEST(Fog, ContinuesThroughAPaneThatAbsorbsNothing) {
    // Through a thin clear pane (transmit 0.5, no absorption) the ray is still between objects:
    // it misses everything and sees the fog colour C, times 0.5, seen through the 10 units of fog
    // before the pane: 0.5·C·e^(−1) + C·(1 − e^(−1)). (Were the child "inside" the pane, its
    // miss would see the black background: 0.5·0·e^(−1) + C·(1 − e^(−1)).)
    Tracer t(R"({"rayo": 1, "fog": {"color": [0.8, 0.6, 0.4], "density": 0.1},
      "materials": {"default": {"ka": 0, "kd": 0, "transmit": 0.5}},
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1}]})");
    const double k = 1.0 - 0.5 * std::exp(-1.0);
    expect_vec3(t.radiance(Vec3(0, 0, 10), Vec3(0, 0, -1)), 0.8 * k, 0.6 * k, 0.4 * k, 1e-6);
}

TEST(Absorption, BeerLambertOverTheChordOfASphere) {
    // A clear sphere (ior 1: rays go straight) of radius 1.5 absorbing σ per unit length, seen
    // against a white background: a ray at distance b from the centre crosses a chord
    // 2√(r² − b²) and keeps exp(−σ·chord) (to the spawned rays' origin offsets, ~1e-4 here).
    Tracer t(R"({"rayo": 1, "background": 1,
      "materials": {"default": {"ka": 0, "kd": 0, "transmit": 1, "absorption": [0.1, 0.5, 2]}},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1.5}]})");
    for (float b : {0.0f, 0.9f}) {
        const double chord = 2.0 * std::sqrt(1.5 * 1.5 - b * b);
        expect_vec3(t.radiance(Vec3(b, 0, 10), Vec3(0, 0, -1)), std::exp(-0.1 * chord),
                    std::exp(-0.5 * chord), std::exp(-2.0 * chord), 5e-4);
    }
}

// A floor lit from straight above through two thin transmissive disks.
const char* const kFilteredScene = R"({"rayo": 1, "render": {"shadows": "SHADOWS"},
  "materials": {"default": {"ka": 0, "kd": 0.5},
                "red": {"ka": 0, "kd": 0, "transmit": [0.9, 0.3, 0.6]},
                "blue": {"ka": 0, "kd": 0, "transmit": [0.5, 0.8, 1]}},
  "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": 2}],
  "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 10},
              {"type": "disk", "center": [0, 2, 0], "normal": [0, 1, 0], "radius": 1,
               "material": "red"},
              {"type": "disk", "center": [0, 3, 0], "normal": [0, -1, 0], "radius": 1,
               "material": "blue"}]})";

std::string filtered_scene(const std::string& mode) {
    std::string text = kFilteredScene;
    return text.replace(text.find("SHADOWS"), 7, mode);
}

TEST(FilteredShadows, LightThroughTransmissiveSurfacesIsTheProductOfTheirColours) {
    // Seen from below the disks (a ray from y = 1 down): kd·I·T_red·T_blue.
    Tracer filtered(filtered_scene("filtered"));
    expect_vec3(filtered.radiance(Vec3(0, 1, 0), Vec3(0, -1, 0)), 0.5 * 2 * 0.9 * 0.5,
                0.5 * 2 * 0.3 * 0.8, 0.5 * 2 * 0.6 * 1.0, 1e-6);
    EXPECT_EQ(filtered.counters.shadow, 1u);
    EXPECT_EQ(filtered.counters.shadow_filtered, 2u);  // continued past each disk
    // Beside the disks nothing is in the way.
    expect_vec3(filtered.radiance(Vec3(3, 1, 0), Vec3(0, -1, 0)), 1.0, 1.0, 1.0, 1e-6);
    // Opaque shadows (the default) stop at the first disk.
    Tracer opaque(filtered_scene("opaque"));
    expect_vec3(opaque.radiance(Vec3(0, 1, 0), Vec3(0, -1, 0)), 0.0, 0.0, 0.0, 0.0);
    EXPECT_EQ(opaque.counters.shadow_filtered, 0u);
}

TEST(FilteredShadows, AbsorbingGlassFiltersByItsTransmitTwiceAndBeerLambertInside) {
    // A box of height 1 between the light and the floor, transmit 0.8 and absorption 0.5: the
    // shadow ray crosses two faces and 1 unit inside: 0.8²·e^(−0.5).
    Tracer t(R"({"rayo": 1, "render": {"shadows": "filtered"},
      "materials": {"default": {"ka": 0, "kd": 1},
                    "glass": {"ka": 0, "kd": 0, "transmit": 0.8, "absorption": 0.5, "ior": 1.5}},
      "lights": [{"type": "directional", "direction": [0, -1, 0]}],
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 10},
                  {"type": "box", "min": [-1, 2, -1], "max": [1, 3, 1], "material": "glass"}]})");
    const double expected = 0.8 * 0.8 * std::exp(-0.5);
    expect_vec3(t.radiance(Vec3(0, 1, 0), Vec3(0, -1, 0)), expected, expected, expected, 5e-5);
}

// ---- Area lights ------------------------------------------------------------------------------

// A white Lambert floor (kd = 1, no ambient) under a disk light of radiance 3, radius 1, height 4
// (normal down), and `extra_objects`.
std::string disk_light_scene(int samples, const std::string& extra_objects = "") {
    return R"({"rayo": 1, "materials": {"default": {"ka": 0, "kd": 1}},
      "lights": [{"type": "area", "shape": "disk", "center": [0, 4, 0], "normal": [0, -1, 0],
                  "radius": 1, "color": [1, 1, 1], "intensity": 3, "samples": )" +
           std::to_string(samples) + R"(}],
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 100})" +
           extra_objects + "]}";
}

TEST(AreaLightScene, FloorUnderADiskLightGetsTheClosedFormIrradiance) {
    // E = π·L·R²/(h² + R²) with L = 3, R = 1, h = 4; the Lambertian floor (kd = 1) reflects
    // E/π (an area light's light is radiometric, docs/radiosity.md).
    Tracer t(disk_light_scene(256));
    const double expected = kPi * 3.0 / (16.0 + 1.0) / kPi;
    const Vec3 e = t.radiance(Vec3(0, 1, 0), Vec3(0, -1, 0));
    EXPECT_NEAR(e.x, expected, 0.01 * expected);
    EXPECT_EQ(t.counters.shadow, 256u);
}

TEST(AreaLightScene, PenumbraWidthFollowsSimilarTriangles) {
    // An opaque half-plane at height a = 2 over x < 0 (its edge along z), the light's disk of
    // radius R = 1 at height H = 4: the floor is fully lit for x ≥ R·a/(H − a) = 1, fully dark for
    // x ≤ −1, and in between partly lit (penumbra width 2R·a/(H − a) = 2).
    const std::string occluder =
        R"(, {"type": "polygon", "vertices": [[-50, 2, -50], [0, 2, -50], [0, 2, 50], [-50, 2, 50]]})";
    Tracer open(disk_light_scene(256));
    Tracer shadowed(disk_light_scene(256, occluder));
    auto at = [](Tracer& t, float x) { return t.radiance(Vec3(x, 1, 0.3f), Vec3(0, -1, 0)).x; };
    for (float x : {1.02f, 1.5f}) {  // outside the penumbra: every sample reaches the light
        EXPECT_EQ(at(shadowed, x), at(open, x)) << x;
        EXPECT_EQ(at(shadowed, -x), 0.0f) << -x;
    }
    for (float x : {-0.7f, -0.3f, 0.3f, 0.7f}) {  // inside: some samples blocked, some not
        EXPECT_GT(at(shadowed, x), 0.0f) << x;
        EXPECT_LT(at(shadowed, x), at(open, x)) << x;
    }
    // Half the disk visible from below the edge.
    EXPECT_NEAR(at(shadowed, 0.0f), 0.5f * at(open, 0.0f), 0.03f * at(open, 0.0f));
}

TEST(AreaLightScene, RaysSeeTheEmittingSideOfTheLight) {
    Tracer t(disk_light_scene(16));
    // From below: the disk's radiance L = 3; from above: its back, black (no ambient).
    expect_vec3(t.radiance(Vec3(0.2f, 1, 0), Vec3(0, 1, 0)), 3.0, 3.0, 3.0, 0.0);
    expect_vec3(t.radiance(Vec3(0.2f, 6, 0), Vec3(0, -1, 0)), 0.0, 0.0, 0.0, 0.0);
    // The emitter is a material of its own, after the file's.
    ASSERT_EQ(t.description.shading.materials.size(), 2u);
    EXPECT_EQ(t.description.shading.materials[1].emission, Vec3(3.0f));
}

TEST(EmissionMaterial, AnObjectSeenByARayShowsItsEmission) {
    Tracer t(R"({"rayo": 1, "materials": {"default": {"ka": 0.1, "kd": 0, "emission": [2, 1, 0.5]}},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})");
    // ka·Ia + emission.
    expect_vec3(t.radiance(Vec3(0, 0, 5), Vec3(0, 0, -1)), 2.1, 1.1, 0.6, 1e-6);
}

// ---- Determinism ------------------------------------------------------------------------------

TEST(LightsMediaDeterminism, SameBitsForAnyThreadCountTileSizeAndStreaming) {
    SceneDescription d = load(R"({"rayo": 1,
      "camera": {"eye": [0, 3, 8], "look_at": [0, 0.5, 0], "width": 96, "height": 72},
      "render": {"shadows": "filtered", "tile_size": 16},
      "fog": {"color": 0.3, "density": 0.05},
      "materials": {"default": {"kd": 0.7},
                    "glass": {"kd": 0, "ka": 0, "transmit": [0.9, 1, 0.9], "ior": 1.5,
                              "fresnel": true, "absorption": 0.2},
                    "leaf": {"kd": 0.3, "translucency": [0.2, 0.6, 0.1]}},
      "lights": [{"type": "area", "shape": "rectangle", "corner": [-1, 4, -1], "edge1": [2, 0, 0],
                  "edge2": [0, 0, 2], "samples": 8, "intensity": 2},
                 {"type": "area", "shape": "sphere", "center": [3, 3, 2], "radius": 0.5,
                  "samples": 4}],
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 20},
                  {"type": "sphere", "center": [-1, 1, 0], "radius": 1, "material": "glass"},
                  {"type": "disk", "center": [1.5, 1, 0], "normal": [1, 0.5, 1], "radius": 0.8,
                   "material": "leaf"}]})");
    // Light side down: the rectangle above the scene emits toward −y (edge1 × edge2).
    const RenderResult reference = render_scene(d, 1, false);
    for (int threads : {2, 3}) {
        for (int tile : {16, 48}) {
            for (bool coherent : {true, false}) {
                d.settings.tile_size = tile;
                d.settings.coherent = coherent;
                const RenderResult r = render_scene(d, threads, false);
                EXPECT_TRUE(same_bits(reference.film, r.film))
                    << "threads " << threads << " tile " << tile << " coherent " << coherent;
                EXPECT_EQ(r.counters.total_rays(), reference.counters.total_rays());
            }
        }
    }
    EXPECT_GT(reference.counters.shadow_filtered, 0u);
}

}  // namespace
}  // namespace rayo

namespace rayo {
namespace {

TEST(SpotLight, AJsonSpotLightsAPlaneWithTheGltfConeFalloff) {
    // A spot 1 above a white Lambertian plane, pointing down, cone 10° to 30°: the point at
    // angle θ from the axis gets kd·Il·f(θ)·cos θ with KHR_lights_punctual's
    // f = clamp((cos θ − cos 30°)/(cos 10° − cos 30°), 0, 1)².
    Tracer t(R"({"rayo": 1, "materials": {"default": {"ka": 0, "kd": 1, "ks": 0}},
      "lights": [{"type": "spot", "position": [0, 0, 1], "direction": [0, 0, -1],
                  "inner_cone_angle": 10, "outer_cone_angle": 30}],
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 10}]})");
    const double inner = std::cos(10.0 * kPi / 180.0), outer = std::cos(30.0 * kPi / 180.0);
    for (const double degrees : {0.0, 5.0, 12.0, 20.0, 28.0, 31.0, 60.0}) {
        const double theta = degrees * kPi / 180.0;
        const double x = std::tan(theta);
        const double f =
            std::pow(std::clamp((std::cos(theta) - outer) / (inner - outer), 0.0, 1.0), 2.0);
        const double expected = f * std::cos(theta);
        const Vec3 r = t.radiance(Vec3(static_cast<float>(x), 0, 5), Vec3(0, 0, -1));
        EXPECT_NEAR(r.x, expected, 2e-5) << degrees << "°";
    }
}

}  // namespace
}  // namespace rayo
