// Progressive renders (core/progressive.h): one pass is the plain render of its samples, the
// image is the same bits for any thread count, tile size and batching, the noise estimate
// (batch means) agrees with the error measured against a high-sample reference, the noise target
// and the time limit stop where they say, and the settings' errors name their pointer.
#include "core/progressive.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <string>
#include <thread>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/error.h"
#include "core/luminance.h"
#include "core/stop_request.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

// A diffuse sphere on a floor under a disk light, path traced: noisy at a few samples.
std::string lit_sphere(const std::string& render) {
    return R"({"rayo": 1, "background": [0, 0, 0],
      "camera": {"eye": [0, 2, 6], "look_at": [0, 0.6, 0], "width": 48, "height": 36},
      "lights": [{"type": "area", "shape": "disk", "center": [0, 4, 0], "normal": [0, -1, 0],
                  "radius": 1, "intensity": 6}],
      "materials": {"default": {"ka": 0, "kd": 0.7, "ks": 0}},
      "render": )" +
           render + R"(,
      "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 10},
                  {"type": "sphere", "center": [0, 1, 0], "radius": 1}]})";
}

SceneDescription load(const std::string& render) {
    return load_json_string(lit_sphere(render), "scene.json", "");
}

std::string path_render(const std::string& progressive) {
    return R"({"integrator": {"type": "path", "max_depth": 4})" +
           (progressive.empty() ? std::string() : ", " + progressive) + "}";
}

TEST(Progressive, OnePassIsThePlainRenderOfItsSamples) {
    const RenderResult plain = render_scene(load(path_render(R"("spp": 4)")), 2, false);
    const RenderResult one_pass = render_scene(
        load(path_render(R"("max_spp": 4, "pass_spp": 4, "time_limit": 1000)")), 2, false);
    ASSERT_TRUE(one_pass.progressive.has_value());
    EXPECT_EQ(one_pass.progressive->passes, 1);
    EXPECT_EQ(one_pass.progressive->spp, 4u);
    EXPECT_EQ(one_pass.progressive->stop, ProgressiveStop::Samples);
    EXPECT_TRUE(std::isnan(one_pass.progressive->noise));
    EXPECT_TRUE(rayo_test::same_bits(plain.film, one_pass.film));
}

TEST(Progressive, SameBitsForAnyThreadCountTileSizeAndBatching) {
    SceneDescription d =
        load(path_render(R"("max_spp": 24, "pass_spp": 4, "noise_target": 1e-6, "tile_size": 16)"));
    const RenderResult reference = render_scene(d, 1, false);
    ASSERT_EQ(reference.progressive->passes, 6);
    for (int threads : {2, 3}) {
        for (int tile : {16, 48}) {
            for (bool coherent : {true, false}) {
                d.settings.tile_size = tile;
                d.settings.coherent = coherent;
                const RenderResult r = render_scene(d, threads, false);
                EXPECT_TRUE(rayo_test::same_bits(reference.film, r.film))
                    << "threads " << threads << " tile " << tile << " coherent " << coherent;
                EXPECT_EQ(r.progressive->noise, reference.progressive->noise);
            }
        }
    }
}

// The relative RMS error of `image` against `reference` (luminance), as the estimate defines it.
double relative_rms_error(const Film& image, const Film& reference) {
    double squares = 0.0, mean = 0.0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const double a = luminance(image.rgb(x, y)), b = luminance(reference.rgb(x, y));
            squares += (a - b) * (a - b);
            mean += b;
        }
    }
    const double pixels = static_cast<double>(image.width()) * image.height();
    return std::sqrt(squares / pixels) / (mean / pixels);
}

TEST(Progressive, TheNoiseEstimateIsTheErrorAgainstAReference) {
    // 16 passes of 4 against a 4096-sample reference. The reference holds the image's own 64
    // samples (the same sample indices): that shrinks the measured error by about 3%, and the
    // reference's own noise adds about 1%.
    const RenderResult image = render_scene(
        load(path_render(R"("max_spp": 64, "pass_spp": 4, "time_limit": 1000)")), 2, false);
    const RenderResult reference = render_scene(load(path_render(R"("spp": 4096)")), 2, false);
    ASSERT_EQ(image.progressive->passes, 16);
    const double measured = relative_rms_error(image.film, reference.film);
    const double estimated = image.progressive->noise;
    EXPECT_GT(measured, 0.01);  // a noisy image, so that the comparison says something
    EXPECT_NEAR(estimated / measured, 1.0, 0.15)
        << "estimated " << estimated << ", measured " << measured;
}

TEST(Progressive, TheNoiseTargetStopsAtOrBelowIt) {
    const RenderResult coarse =
        render_scene(load(path_render(R"("pass_spp": 4, "noise_target": 0.08)")), 2, false);
    const RenderResult fine =
        render_scene(load(path_render(R"("pass_spp": 4, "noise_target": 0.04)")), 2, false);
    for (const RenderResult* r : {&coarse, &fine}) {
        ASSERT_TRUE(r->progressive.has_value());
        EXPECT_EQ(r->progressive->stop, ProgressiveStop::NoiseTarget);
        EXPECT_GE(r->progressive->passes, kMinNoisePasses);
        EXPECT_EQ(r->progressive->spp, static_cast<uint32_t>(r->progressive->passes) * 4u);
    }
    EXPECT_LE(coarse.progressive->noise, 0.08);
    EXPECT_LE(fine.progressive->noise, 0.04);
    // Monte Carlo: half the noise takes about four times the samples.
    const double ratio = static_cast<double>(fine.progressive->spp) / coarse.progressive->spp;
    EXPECT_GT(ratio, 2.5);
    EXPECT_LT(ratio, 6.0);
}

TEST(Progressive, TheTimeLimitStopsAfterThePassThatCrossesIt) {
    // Any pass of this render takes longer than a millisecond: the first one crosses the limit.
    const RenderResult r =
        render_scene(load(path_render(R"("pass_spp": 8, "time_limit": 0.001)")), 2, false);
    ASSERT_TRUE(r.progressive.has_value());
    EXPECT_EQ(r.progressive->stop, ProgressiveStop::TimeLimit);
    EXPECT_EQ(r.progressive->passes, 1);
    EXPECT_GE(r.render_seconds, 0.001);
}

TEST(Progressive, TheSampleCapStopsWholePasses) {
    const RenderResult r = render_scene(
        load(path_render(R"("max_spp": 10, "pass_spp": 4, "noise_target": 1e-6)")), 2, false);
    EXPECT_EQ(r.progressive->stop, ProgressiveStop::Samples);
    EXPECT_EQ(r.progressive->spp, 8u);  // a third pass would pass the cap
}

TEST(Progressive, AStopRequestDropsTheUnfinishedPassAndDeliversNothing) {
    // A render that would run for hours, stopped from another thread as an interrupt would.
    std::thread stopper([] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        request_stop(SIGINT);
    });
    const RenderResult r =
        render_scene(load(path_render(R"("pass_spp": 4, "noise_target": 1e-6)")), 2, false);
    stopper.join();
    request_stop(0);
    ASSERT_TRUE(r.progressive.has_value());
    EXPECT_EQ(r.progressive->stop, ProgressiveStop::Interrupted);
    for (const float v : r.film.rgba()) ASSERT_EQ(v, 0.0f);  // nothing delivered to the film
}

TEST(Progressive, BadSettingsAreRefusedAtTheirPointer) {
    auto error_of = [](const std::string& render) {
        try {
            load(render);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(error_of(R"({"time_limit": 0})").find("/render/time_limit"), std::string::npos);
    EXPECT_NE(error_of(R"({"noise_target": 0})").find("/render/noise_target"), std::string::npos);
    EXPECT_NE(error_of(R"({"noise_target": -0.1})").find("/render/noise_target"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"pass_spp": 1})").find("/render/pass_spp"), std::string::npos);
    const std::string adaptive = error_of(R"({"aa": "adaptive", "noise_target": 0.1})");
    EXPECT_NE(adaptive.find("/render/aa"), std::string::npos) << adaptive;
    EXPECT_NE(adaptive.find("own stopping rule"), std::string::npos) << adaptive;
    const std::string cap = error_of(R"({"max_spp": 2, "pass_spp": 4, "time_limit": 1})");
    EXPECT_NE(cap.find("/render/max_spp"), std::string::npos) << cap;
    EXPECT_NE(cap.find("below one pass"), std::string::npos) << cap;
    EXPECT_NE(error_of(R"({"max_spp": 1})").find("/render/max_spp"), std::string::npos);
    EXPECT_EQ(error_of(R"({"max_spp": 8, "pass_spp": 4, "time_limit": 1})"), "accepted");
    // A plain render's spp is not a progressive render's business: both may be given.
    EXPECT_EQ(error_of(R"({"spp": 2, "pass_spp": 4, "noise_target": 0.1})"), "accepted");
}

}  // namespace
}  // namespace rayo
