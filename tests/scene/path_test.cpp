// The path integrator (shading/integrators/path.h) against closed forms and against itself:
// the white furnace (a closed box of albedo ρ that emits E everywhere holds radiance E/(1 − ρ)),
// a disk light's direct light on a Lambertian floor (ρ·L·r²/(r² + h²)) from light sampling only,
// BSDF sampling only and their MIS combination, the three strategies agreeing on a glossy floor,
// a point light's direct light equal to Whitted's, determinism over threads and tiles, and the
// settings' errors.
#include "shading/integrators/path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/accel.h"
#include "core/error.h"
#include "shading/integrators/integrator.h"
#include "tests/scene/path_estimate.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

SceneDescription load(const std::string& text) {
    return load_json_string(text, "scene.json", "");
}

using rayo_test::Estimate;
using rayo_test::estimate_along;

// A closed cube [-1, 1]³ of six polygons wound inward, so their emitting front faces the inside
// (or outward: the inside then sees their backs).
std::string inward_cube(bool outward = false) {
    std::ostringstream out;
    bool first = true;
    for (int axis = 0; axis < 3; ++axis) {
        for (int side : {-1, 1}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            // Counter-clockwise about −side along the axis: the winding normal points inward.
            const int corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            out << (first ? "" : ", ") << R"({"type": "polygon", "vertices": [)";
            first = false;
            for (int k = 0; k < 4; ++k) {
                const int c = (side > 0) != outward ? 3 - k : k;
                int p[3];
                p[axis] = side;
                p[u] = corners[c][0];
                p[v] = corners[c][1];
                out << (k ? ", " : "") << "[" << p[0] << ", " << p[1] << ", " << p[2] << "]";
            }
            out << "]}";
        }
    }
    return out.str();
}

TEST(PathIntegrator, TheInwardCubeIsWoundInward) {
    // The furnace below relies on it: the camera inside sees every face's front.
    const SceneDescription d = load(R"({"rayo": 1, "objects": [)" + inward_cube() + "]}");
    const Accel accel(d.scene, AccelOptions{});
    for (const Vec3& direction :
         {Vec3(1, 0.1f, 0.2f), Vec3(-1, 0.2f, 0.1f), Vec3(0.1f, 1, 0.2f), Vec3(0.2f, -1, 0.1f),
          Vec3(0.1f, 0.2f, 1), Vec3(0.2f, 0.1f, -1)}) {
        Ray ray;
        ray.direction = glm::normalize(direction);
        SurfaceHit hit;
        ASSERT_TRUE(accel.intersect(ray, hit));
        EXPECT_LT(glm::dot(hit.geometric_normal, ray.direction), 0.0f) << direction.x;
    }
}

TEST(PathIntegrator, AWhiteFurnaceHoldsEmissionOverOneMinusAlbedo) {
    for (const double albedo : {0.5, 0.9}) {
        const double emission = 0.25;
        std::ostringstream text;
        text << R"({"rayo": 1, "background": [0, 0, 0],
          "materials": {"default": {"ka": 0, "kd": )"
             << albedo << R"(, "emission": )" << emission << R"(}},
          "render": {"integrator": {"type": "path", "max_depth": 1024}},
          "objects": [)"
             << inward_cube() << "]}";
        const SceneDescription d = load(text.str());
        // The path length is geometric (mean 1/(1 − ρ)): ρ = 0.9 needs the more samples.
        const uint32_t samples = albedo > 0.5 ? 1u << 20 : 1u << 18;
        const Estimate e =
            estimate_along(d, Vec3(0.1f, -0.2f, 0.3f), Vec3(0.3f, 0.5f, -1), samples);
        const double expected = emission / (1.0 - albedo);
        EXPECT_NEAR(e.mean, expected, 0.005 * expected) << "albedo " << albedo;
        EXPECT_LT(e.standard_error, 0.0017 * expected) << "the test cannot resolve 0.5%";
    }
}

TEST(PathIntegrator, AnOutwardWoundFurnaceIsTheSameFurnaceUnlessOneSided) {
    // The camera inside sees every wall's back. Two-sided (the default), a back emits and
    // scatters as a front does: E/(1 − ρ) within the inward furnace's 0.5%. One-sided, a back
    // emits nothing (its scattering is as before, two-sided lobes): the box is black.
    for (const std::string sidedness : {"", R"(, "double_sided": false)"}) {
        SCOPED_TRACE(sidedness);
        const double albedo = 0.5, emission = 0.25;
        std::ostringstream text;
        text << R"({"rayo": 1, "background": [0, 0, 0],
          "materials": {"default": {"ka": 0, "kd": )"
             << albedo << R"(, "emission": )" << emission << sidedness << R"(}},
          "render": {"integrator": {"type": "path", "max_depth": 1024}},
          "objects": [)"
             << inward_cube(true) << "]}";
        const SceneDescription d = load(text.str());
        const Estimate e =
            estimate_along(d, Vec3(0.1f, -0.2f, 0.3f), Vec3(0.3f, 0.5f, -1), 1u << 18);
        const double expected = sidedness.empty() ? emission / (1.0 - albedo) : 0.0;
        EXPECT_NEAR(e.mean, expected, 0.005 * emission / (1.0 - albedo));
        if (!sidedness.empty()) EXPECT_EQ(e.mean, 0.0);
    }
}

std::string disk_light_scene(const std::string& strategy, const std::string& floor) {
    return R"({"rayo": 1, "background": [0, 0, 0], "ambient_light": 0,
      "materials": {"default": )" +
           floor + R"(},
      "lights": [{"type": "area", "shape": "disk", "center": [0, 2, 0], "normal": [0, -1, 0],
                  "radius": 1, "intensity": 10, "samples": 1}],
      "render": {"integrator": {"type": "path", "max_depth": 1, "strategy": ")" +
           strategy + R"("}},
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 20}]})";
}

TEST(PathIntegrator, EveryStrategyGivesADiskLightsDirectLight) {
    // A disk of radiance L and radius r at height h straight above the point gives the
    // irradiance π·L·r²/(r² + h²); a Lambertian floor of albedo ρ sends ρ/π of it.
    const double rho = 0.5, radiance = 10.0, r = 1.0, h = 2.0;
    const double expected = rho * radiance * r * r / (r * r + h * h);
    for (const char* strategy : {"mis", "light", "bsdf"}) {
        const SceneDescription d = load(disk_light_scene(strategy, R"({"ka": 0, "kd": 0.5})"));
        const Estimate e = estimate_along(d, Vec3(0, 1, 3), Vec3(0, -1, -3), 1 << 18);
        EXPECT_NEAR(e.mean, expected, 4.0 * e.standard_error + 1e-4 * expected) << strategy;
        EXPECT_LT(e.standard_error, 0.005 * expected) << strategy;
    }
}

TEST(PathIntegrator, TheStrategiesAgreeOnAGlossyFloor) {
    // No closed form for the modified Phong lobe under a disk, but all three estimators are
    // unbiased: their means agree within their standard errors.
    const std::string floor = R"({"ka": 0, "kd": 0.3, "ks": 0.6, "shininess": 400})";
    Estimate e[3];
    const char* names[3] = {"mis", "light", "bsdf"};
    for (int k = 0; k < 3; ++k) {
        e[k] = estimate_along(load(disk_light_scene(names[k], floor)), Vec3(0, 1.5f, 0.5f),
                              Vec3(0, -1.5f, -0.5f), 1 << 17);
    }
    for (int a = 0; a < 3; ++a) {
        for (int b = a + 1; b < 3; ++b) {
            const double tolerance = 4.0 * std::hypot(e[a].standard_error, e[b].standard_error);
            EXPECT_NEAR(e[a].mean, e[b].mean, tolerance) << names[a] << " vs " << names[b];
        }
    }
    // MIS is never much worse than the better of the two (Veach & Guibas 1995) and here, a
    // sharp highlight on a diffuse base, better than the worse by far.
    const double better = std::min(e[1].standard_error, e[2].standard_error);
    const double worse = std::max(e[1].standard_error, e[2].standard_error);
    EXPECT_LE(e[0].standard_error, 1.3 * better);
    EXPECT_LE(e[0].standard_error, 0.5 * worse);
    std::cout << "standard errors: mis " << e[0].standard_error << ", light " << e[1].standard_error
              << ", bsdf " << e[2].standard_error << "\n";
}

TEST(PathIntegrator, APointLightsDirectLightIsWhitteds) {
    // Seed 000's Il is what a white Lambertian surface facing the light reflects: the path
    // integrator's kd/π times the irradiance π·Il gives Whitted's kd·Il·(N·L).
    const SceneDescription d = load(R"({"rayo": 1, "background": [0, 0, 0], "ambient_light": 0,
      "materials": {"default": {"ka": 0, "kd": [0.6, 0.4, 0.2]}},
      "lights": [{"type": "point", "position": [1, 3, -0.5], "color": [1, 0.9, 0.8],
                  "intensity": 2}],
      "render": {"integrator": {"type": "path", "max_depth": 1}},
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 20}]})");
    const Accel accel(d.scene, AccelOptions{});
    const IntegratorContext context{accel, d.shading};
    const PathIntegrator path(context, std::get<PathSettings>(d.settings.integrator));
    const WhittedIntegrator whitted(context, WhittedSettings{});
    Ray ray;
    ray.origin = Vec3(0.5f, 2, 3);
    ray.direction = glm::normalize(Vec3(-0.3f, -2, -3));
    RayCounters counters;
    const PixelSample sample{1, 2, 0, 1};
    const Vec3 expected = whitted.radiance(ray, sample, counters);
    ASSERT_GT(expected.x, 0.01f);
    rayo_test::expect_vec_near(path.radiance(ray, sample, counters), expected, 1e-5 * expected.x);
}

TEST(PathIntegrator, SameBitsForAnyThreadCountTileSizeAndBatching) {
    SceneDescription d = load(R"({"rayo": 1,
      "camera": {"eye": [0, 3, 8], "look_at": [0, 0.5, 0], "width": 64, "height": 48},
      "materials": {"glass": {"kd": 0, "ka": 0, "transmit": 1, "ior": 1.5, "fresnel": true},
                    "default": {"kd": 0.7, "ks": 0.2, "shininess": 20}},
      "lights": [{"type": "area", "shape": "disk", "center": [0, 4, 0], "normal": [0, -1, 0],
                  "radius": 1},
                 {"type": "point", "position": [3, 3, 3], "intensity": 0.5}],
      "render": {"spp": 2, "tile_size": 16, "integrator": {"type": "path"}},
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 20},
                  {"type": "sphere", "center": [-1, 1, 0], "radius": 1, "material": "glass"},
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

TEST(PathIntegrator, SettingsErrorsNameThePointerAndTheExpectation) {
    const struct {
        const char* text;
        const char* message;
    } cases[] = {
        {R"({"rayo": 1, "render": {"integrator": {"type": "path", "max_depth": 0}}})",
         "scene.json#/render/integrator/max_depth: expected an integer in [1, 1024], got 0"},
        {R"({"rayo": 1, "render": {"integrator": {"type": "path", "strategy": "both"}}})",
         "scene.json#/render/integrator/strategy: expected one of"},
        {R"({"rayo": 1, "render": {"integrator": {"type": "path", "samples": 4}}})",
         "scene.json#/render/integrator/samples: unknown key \"samples\""},
        {R"({"rayo": 1, "render": {"integrator": {"type": "path", "roulette_depth": -1}}})",
         "scene.json#/render/integrator/roulette_depth: expected an integer in [0, 1024], got -1"},
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
    const SceneDescription d = load(
        R"({"rayo": 1, "render": {"integrator": {"type": "path", "max_depth": 5,
            "roulette_depth": 2, "strategy": "bsdf"}}})");
    const auto& p = std::get<PathSettings>(d.settings.integrator);
    EXPECT_EQ(p.max_depth, 5);
    EXPECT_EQ(p.roulette_depth, 2);
    EXPECT_EQ(p.strategy, LightStrategy::Bsdf);
}

}  // namespace
}  // namespace rayo
