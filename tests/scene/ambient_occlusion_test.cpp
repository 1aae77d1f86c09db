// The ambient-occlusion integrator (shading/integrators/ambient_occlusion.h) against closed
// forms: a plane under an empty sky sees all of its cosine-weighted hemisphere (1), a point inside
// a closed box none of it (0), a point on a floor beside a very large wall half of it, and with a
// finite distance D the wall at distance d hides the share of the hemisphere whose direction
// reaches it within D: Malley's method maps the cosine-weighted hemisphere to the uniform unit
// disk, where those directions are the disk segment x > d/D, of area acos(a) − a·√(1 − a²)
// (a = d/D), over π. Also: the settings through the JSON reader, and the errors.
#include "shading/integrators/ambient_occlusion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/accel.h"
#include "core/error.h"
#include "shading/integrators/integrator.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

SceneDescription load(const std::string& text) {
    return load_json_string(text, "scene.json", "");
}

// The mean AO radiance along one ray over `pixel_samples` camera samples of one pixel.
double mean_along(const std::string& text, const Vec3& origin, const Vec3& direction,
                  uint32_t pixel_samples) {
    const SceneDescription d = load(text);
    const Accel accel(d.scene, AccelOptions{});
    const IntegratorContext context{accel, d.shading};
    const AmbientOcclusionIntegrator integrator(
        context, std::get<AmbientOcclusionSettings>(d.settings.integrator));
    Ray ray;
    ray.origin = origin;
    ray.direction = glm::normalize(direction);
    RayCounters counters;
    double sum = 0.0;
    for (uint32_t s = 0; s < pixel_samples; ++s) {
        sum += integrator.radiance(ray, PixelSample{3, 5, s, pixel_samples}, counters).x;
    }
    return sum / pixel_samples;
}

std::string ao_scene(const std::string& integrator, const std::string& objects) {
    return R"({"rayo": 1, "background": [0, 0, 0],
      "materials": {"default": {"ka": 0, "kd": 1}},
      "render": {"integrator": )" +
           integrator + R"(}, "objects": [)" + objects + "]}";
}

const char* const kFloor = R"({"type": "box", "min": [-1e5, -1e5, -1], "max": [1e5, 1e5, 0]})";
// A wall whose face is at x = 1, one unit from the point of the floor at the origin.
const char* const kWall = R"({"type": "box", "min": [1, -1e5, 0], "max": [2, 1e5, 1e5]})";

TEST(AmbientOcclusion, APlaneUnderAnEmptySkyIsOne) {
    const std::string text = ao_scene(R"({"type": "ambient_occlusion", "samples": 64})", kFloor);
    EXPECT_EQ(mean_along(text, Vec3(0, 0, 5), Vec3(0.1f, 0.2f, -1), 4), 1.0);
}

TEST(AmbientOcclusion, APointInsideAClosedBoxIsZero) {
    const std::string text = ao_scene(R"({"type": "ambient_occlusion", "samples": 64})",
                                      R"({"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1]})");
    EXPECT_EQ(mean_along(text, Vec3(0, 0, 0), Vec3(0.3f, -0.2f, -1), 4), 0.0);
}

TEST(AmbientOcclusion, AVeryLargeWallHidesHalfOfTheHemisphere) {
    const std::string text = ao_scene(R"({"type": "ambient_occlusion", "samples": 1024})",
                                      std::string(kFloor) + ", " + kWall);
    EXPECT_NEAR(mean_along(text, Vec3(0, 0, 5), Vec3(0, 0, -1), 64), 0.5, 0.005);
}

TEST(AmbientOcclusion, AFiniteDistanceHidesTheDiskSegmentItReaches) {
    for (const double distance : {1.25, 2.0, 4.0, 1000.0}) {
        const double a = 1.0 / distance;  // the wall is at d = 1
        const double hidden = (std::acos(a) - a * std::sqrt(1.0 - a * a)) / kPi;
        const std::string text =
            ao_scene(R"({"type": "ambient_occlusion", "samples": 1024, "distance": )" +
                         std::to_string(distance) + "}",
                     std::string(kFloor) + ", " + kWall);
        EXPECT_NEAR(mean_along(text, Vec3(0, 0, 5), Vec3(0, 0, -1), 64), 1.0 - hidden,
                    0.01 * (1.0 - hidden))
            << "distance " << distance;
    }
}

TEST(AmbientOcclusion, TimesTheDiffuseColourPlusTheLightsWhenAsked) {
    // kd 0.5 under an empty sky: 0.5; with "direct", a unit point light straight above adds
    // seed 000's kd·Il·(N·L) = 0.5 at normal incidence.
    const std::string scene = R"({"rayo": 1, "materials": {"default": {"kd": 0.5}},
      "lights": [{"type": "point", "position": [0, 0, 3]}],
      "render": {"integrator": {"type": "ambient_occlusion", "samples": 16, "direct": DIRECT}},
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 10}]})";
    auto with = [&](const char* direct) {
        std::string text = scene;
        text.replace(text.find("DIRECT"), 6, direct);
        return mean_along(text, Vec3(0, 0, 5), Vec3(0, 0, -1), 1);
    };
    EXPECT_NEAR(with("false"), 0.5, 1e-6);
    EXPECT_NEAR(with("true"), 1.0, 1e-5);
}

TEST(AmbientOcclusion, SameBitsForAnyThreadCountTileSizeAndBatching) {
    // The hemisphere's rays come from the sampler (pixel, sample index, dimension), so the
    // image cannot depend on which thread, tile or batch traced a pixel.
    SceneDescription d = load(R"({"rayo": 1,
      "camera": {"eye": [0, 3, 8], "look_at": [0, 0.5, 0], "width": 80, "height": 60},
      "lights": [{"type": "area", "shape": "disk", "center": [0, 4, 0], "normal": [0, -1, 0],
                  "radius": 1, "samples": 4}],
      "render": {"spp": 2, "tile_size": 16, "integrator": {"type": "ambient_occlusion",
                 "samples": 8, "distance": 3, "direct": true}},
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 20},
                  {"type": "sphere", "center": [-1, 1, 0], "radius": 1},
                  {"type": "box", "min": [0.5, 0, -1], "max": [2, 1.5, 0.5]}]})");
    const RenderResult reference = render_scene(d, 1, false);
    for (int threads : {2, 3}) {
        for (int tile : {16, 48}) {
            for (bool coherent : {true, false}) {
                d.settings.tile_size = tile;
                d.settings.coherent = coherent;
                const RenderResult r = render_scene(d, threads, false);
                EXPECT_TRUE(rayo_test::same_bits(reference.film, r.film))
                    << "threads " << threads << " tile " << tile << " coherent " << coherent;
            }
        }
    }
}

TEST(IntegratorSettings, JsonNamesTheIntegratorAndItsFields) {
    const SceneDescription d = load(
        R"({"rayo": 1, "render": {"integrator": {"type": "ambient_occlusion", "samples": 8,
            "distance": 2.5, "direct": true}}})");
    const auto& ao = std::get<AmbientOcclusionSettings>(d.settings.integrator);
    EXPECT_EQ(ao.samples, 8);
    EXPECT_EQ(ao.distance, 2.5f);
    EXPECT_TRUE(ao.direct);
    // Whitted is the default, and its settings may also sit in the render object itself.
    const SceneDescription w = load(
        R"({"rayo": 1, "render": {"max_depth": 3, "integrator": {"type": "whitted",
            "shadows": "filtered"}}})");
    EXPECT_EQ(w.settings.whitted().max_depth, 3);
    EXPECT_EQ(w.settings.whitted().shadows, ShadowMode::Filtered);
    EXPECT_EQ(load(R"({"rayo": 1})").settings.integrator.index(), 0u);
}

TEST(IntegratorSettings, ErrorsNameThePointerAndTheExpectation) {
    const struct {
        const char* text;
        const char* message;
    } cases[] = {
        {R"({"rayo": 1, "render": {"integrator": {"type": "paths"}}})",
         "scene.json#/render/integrator/type: expected one of \"whitted\", "
         "\"ambient_occlusion\", \"path\", got the string \"paths\""},
        {R"({"rayo": 1, "render": {"integrator": {"samples": 4}}})",
         "scene.json#/render/integrator"},
        {R"({"rayo": 1, "render": {"integrator": {"type": "ambient_occlusion", "samples": 0}}})",
         "scene.json#/render/integrator/samples: expected an integer in [1, 4096], got 0"},
        {R"({"rayo": 1, "render": {"integrator": {"type": "ambient_occlusion", "max_depth": 2}}})",
         "scene.json#/render/integrator/max_depth: unknown key \"max_depth\""},
        {R"({"rayo": 1, "render": {"max_depth": 2, "integrator": {"type": "ambient_occlusion"}}})",
         "scene.json#/render/max_depth: a setting of the \"whitted\" integrator, but this "
         "render's integrator is \"ambient_occlusion\""},
        {R"({"rayo": 1, "render": {"integrator": {"type": "ambient_occlusion", "direct": 1}}})",
         "scene.json#/render/integrator/direct: expected true or false, got 1"},
        {R"({"rayo": 1, "render": {"integrator": {"type": "ambient_occlusion",
             "distance": -1}}})",
         "scene.json#/render/integrator/distance: expected a number >= 0, got -1"},
    };
    for (const auto& c : cases) {
        try {
            load(c.text);
            ADD_FAILURE() << "accepted: " << c.text;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos)
                << e.what() << "\nexpected: " << c.message;
        }
    }
}

TEST(IntegratorSettings, TheRegistryNamesEveryIntegratorOnce) {
    EXPECT_EQ(integrator_names(), "\"whitted\", \"ambient_occlusion\", \"path\"");
    ASSERT_TRUE(integrator_named("ambient_occlusion"));
    EXPECT_EQ(integrator_named("ambient_occlusion")->index(), 1u);
    EXPECT_FALSE(integrator_named("Whitted"));
}

}  // namespace
}  // namespace rayo
