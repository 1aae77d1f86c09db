// The environment light (shading/environment_light.h) and the path integrator under it: a
// sphere inside a uniform environment of radiance L shows L times its lobe's albedo (a lobe that
// loses or creates energy shows here), the image's importance sampling is a density (it
// integrates to 1 and its samples carry the pdf that pdf() reports), the mapping puts the image's
// centre at −z, the strategies agree under an image, and the errors of the scene file and of
// --environment (tests write their own small HDR images).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "apps/scene/json_loader.h"
#include "core/accel.h"
#include "core/error.h"
#include "core/sampling.h"
#include "shading/environment_light.h"
#include "shading/integrators/path.h"
#include "tests/scene/path_estimate.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

std::string temp_path(const std::string& name) {
    return ::testing::TempDir() + name;
}

void write_exr(const std::string& path, int width, int height, const std::vector<float>& rgb) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    ASSERT_TRUE(out->open(path, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()));
    out->close();
}

// A 64×32 sky: dim blue everywhere, a bright 3×2 "sun" at column 40, row 8, and black below
// the horizon.
std::string write_sky(const std::string& name) {
    const int w = 64, h = 32;
    std::vector<float> rgb;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const bool sun = x >= 40 && x < 43 && y >= 8 && y < 10;
            const bool below = y >= h / 2;
            const float r = sun ? 200.0f : below ? 0.0f : 0.2f;
            rgb.insert(rgb.end(), {r,
                                   sun     ? 180.0f
                                   : below ? 0.0f
                                           : 0.3f,
                                   sun     ? 150.0f
                                   : below ? 0.0f
                                           : 0.6f});
        }
    }
    const std::string path = temp_path(name);
    write_exr(path, w, h, rgb);
    return path;
}

using rayo_test::Estimate;
using rayo_test::estimate_along;

TEST(EnvironmentLight, ASphereInAUniformEnvironmentShowsItsAlbedo) {
    const struct {
        const char* material;
        double albedo;
    } cases[] = {
        {R"({"ka": 0, "kd": 0.5})", 0.5},
        {R"({"ka": 0, "kd": 0, "reflect": 1})", 1.0},
        {R"({"ka": 0, "kd": 0, "transmit": 1, "ior": 1.5, "fresnel": true})", 1.0},
        {R"({"ka": 0, "kd": 0.5, "translucency": 0.5})", 1.0},
        {R"({"ka": 0, "kd": 0.8, "ks": 0.2, "shininess": 30})", -1.0},  // at most 1
    };
    const double radiance = 2.0;
    for (const auto& c : cases) {
        const std::string text = std::string(R"({"rayo": 1, "background": [0, 0, 0],
          "environment": {"color": [1, 1, 1], "intensity": 2},
          "materials": {"default": )") +
                                 c.material + R"(},
          "render": {"integrator": {"type": "path", "max_depth": 64}},
          "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})";
        const SceneDescription d = load_json_string(text, "scene.json", "");
        // Off-centre, so the ray meets the sphere obliquely.
        const Estimate e = estimate_along(d, Vec3(0.3f, 0.4f, 5), Vec3(0, 0, -1), 1 << 16, 0, 7, 2);
        if (c.albedo < 0.0) {
            EXPECT_LE(e.mean, radiance + 4.0 * e.standard_error) << c.material;
            EXPECT_GT(e.mean, 0.5 * radiance) << c.material;
        } else {
            EXPECT_NEAR(e.mean, radiance * c.albedo,
                        4.0 * e.standard_error + 1e-4 * radiance * c.albedo)
                << c.material;
            EXPECT_LT(e.standard_error, 0.004 * radiance) << c.material;
        }
    }
}

TEST(EnvironmentLight, ImportanceSamplingIsADensityItsSamplesReport) {
    const std::string path = write_sky("sky_density.exr");
    const SceneDescription d = load_json_string(
        R"({"rayo": 1, "environment": {"image": ")" + path + R"(", "rotation": 30}})", "scene.json",
        "");
    ASSERT_EQ(d.shading.environment, 0);
    const auto& light = std::get<EnvironmentLight>(d.shading.lights[0]);
    // ∫ pdf dω over the sphere, by uniform directions: 4π·mean(pdf) = 1.
    const int n = 1 << 18;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const float z = 1.0f - 2.0f * sample_uniform(1, 2, i, 0);
        const float phi = 2.0f * kPi * sample_uniform(1, 2, i, 1);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        sum += light.pdf(Vec3(0.0f), Vec3(r * std::cos(phi), z, r * std::sin(phi)));
    }
    EXPECT_NEAR(4.0 * kPi * sum / n, 1.0, 0.01);
    // Its samples carry pdf(direction) and the radiance seen along that direction, and they go
    // to the sun in proportion to its weight (largest channel × sin θ of the row): 6 texels of
    // 200 at sin(8.5π/32) against the upper half's 0.6·sin θ per texel, 69% of the total.
    int toward_sun = 0;
    for (int i = 0; i < 4096; ++i) {
        LightSample s;
        const glm::vec2 u(sample_uniform(3, 4, i, 0), sample_uniform(3, 4, i, 1));
        if (!light.sample(Vec3(0.0f), u, s)) continue;
        EXPECT_NEAR(s.pdf, light.pdf(Vec3(0.0f), s.direction), 1e-3f * s.pdf);
        rayo_test::expect_vec_near(s.radiance, light.radiance(s.direction), 1e-4f * s.radiance.x);
        if (s.radiance.x > 100.0f) ++toward_sun;
    }
    EXPECT_NEAR(toward_sun / 4096.0, 0.69, 0.03);
}

TEST(EnvironmentLight, TheImagesCentreLooksAlongMinusZAndRotationTurnsIt) {
    // A 4×2 image whose four columns differ: u = 0.5 + atan2(x, −z)/2π puts column 2's left
    // edge at −z and column 3 toward +x.
    const std::string path = temp_path("columns.exr");
    std::vector<float> rgb;
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 4; ++x) rgb.insert(rgb.end(), {float(x + 1), 0.0f, 0.0f});
    }
    write_exr(path, 4, 2, rgb);
    SceneDescription d = load_json_string(
        R"({"rayo": 1, "environment": {"image": ")" + path + R"("}})", "scene.json", "");
    auto& light = std::get<EnvironmentLight>(d.shading.lights[0]);
    const Vec3 ahead = glm::normalize(Vec3(0.1f, 0.2f, -1));  // just right of −z
    EXPECT_EQ(light.radiance(ahead).x, 3.0f);
    // u = 0.80 and 0.20: past +x and past −x, toward +z.
    EXPECT_EQ(light.radiance(glm::normalize(Vec3(1, 0.1f, 0.3f))).x, 4.0f);
    EXPECT_EQ(light.radiance(glm::normalize(Vec3(-1, 0.1f, 0.3f))).x, 1.0f);
    // Turned by 90° about +y, what was ahead (−z) is now toward −x.
    light.rotation = 90.0f;
    EXPECT_EQ(light.radiance(glm::normalize(Vec3(-1, 0.2f, -0.1f))).x, 3.0f);
}

TEST(EnvironmentLight, TheStrategiesAgreeUnderAnImage) {
    const std::string path = write_sky("sky_strategies.exr");
    Estimate e[3];
    const char* names[3] = {"mis", "light", "bsdf"};
    for (int k = 0; k < 3; ++k) {
        const SceneDescription d = load_json_string(
            R"({"rayo": 1, "environment": {"image": ")" + path +
                R"("}, "materials": {"default": {"ka": 0, "kd": 0.5, "ks": 0.3, "shininess": 50}},
              "render": {"integrator": {"type": "path", "max_depth": 1, "strategy": ")" +
                names[k] + R"("}},
              "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0],
                           "radius": 100}]})",
            "scene.json", "");
        e[k] = estimate_along(d, Vec3(0, 1, 1), Vec3(0, -1, -1), 1 << 16, 0, 7, 2);
    }
    for (int a = 0; a < 3; ++a) {
        for (int b = a + 1; b < 3; ++b) {
            EXPECT_NEAR(e[a].mean, e[b].mean,
                        4.0 * std::hypot(e[a].standard_error, e[b].standard_error))
                << names[a] << " vs " << names[b];
        }
    }
    // A small bright sun: BSDF sampling alone is far noisier than MIS.
    EXPECT_LT(e[0].standard_error, 0.5 * e[2].standard_error);
}

std::string error_of(const std::string& text) {
    try {
        load_json_string(text, "s.json", ::testing::TempDir());
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(EnvironmentLight, BadInputNamesThePlace) {
    write_exr(temp_path("square.exr"), 8, 8, std::vector<float>(8 * 8 * 3, 1.0f));
    std::vector<float> negative(8 * 4 * 3, 1.0f);
    negative[3 * 9 + 1] = -1.0f;
    write_exr(temp_path("negative.exr"), 8, 4, negative);
    write_exr(temp_path("fine.exr"), 8, 4, std::vector<float>(8 * 4 * 3, 1.0f));
    const struct {
        const char* text;
        const char* message;
    } cases[] = {
        {R"({"rayo": 1, "environment": {"image": "missing.exr"}})",
         "s.json#/environment/image: cannot open environment image"},
        {R"({"rayo": 1, "environment": {"image": "square.exr"}})",
         "square.exr' is 8x8: expected an equirectangular image, twice as wide as high"},
        {R"({"rayo": 1, "environment": {"image": "negative.exr"}})",
         "has a negative or non-finite value at pixel (1, 1)"},
        {R"({"rayo": 1, "environment": {"image": 3}})",
         "s.json#/environment/image: expected a path to an image file, got 3"},
        {R"({"rayo": 1, "environment": {"intensity": -1}})", "s.json#/environment/intensity"},
        {R"({"rayo": 1, "environment": {"samples": 0}})",
         "s.json#/environment/samples: expected an integer in [1, 4096]"},
        {R"({"rayo": 1, "environment": {"colour": 1}})", "s.json#/environment/colour: unknown key"},
        {R"({"rayo": 1, "environment": {"image": "fine.exr"},
             "lights": [{"type": "environment"}]})",
         "s.json#/environment: a second environment light: a scene has at most one"},
        {R"({"rayo": 1, "lights": [{"type": "environment"}, {"type": "environment"}]})",
         "s.json#/lights/1: a second environment light"},
    };
    for (const auto& c : cases) {
        const std::string message = error_of(c.text);
        EXPECT_NE(message.find(c.message), std::string::npos)
            << message << "\nexpected: " << c.message;
    }
    // A light of type "environment" in the list is the same light.
    const SceneDescription d = load_json_string(
        R"({"rayo": 1, "lights": [{"type": "point", "position": [0, 1, 0]},
            {"type": "environment", "image": "fine.exr", "intensity": 0.5}]})",
        "s.json", ::testing::TempDir());
    EXPECT_EQ(d.shading.environment, 1);
    EXPECT_EQ(d.shading.escaped(Vec3(0, 1, 0)), Vec3(0.5f));
}

}  // namespace
}  // namespace rayo
