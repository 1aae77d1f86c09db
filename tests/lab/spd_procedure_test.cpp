// The SPD's testing procedure (bench/lab/spd_procedure.h) and what `rayo bench suite` writes
// for it: the exact corner count of aa "corners", the Readme comparison, the failure lines, and
// suite.json in Google Benchmark's form read back with nlohmann-json.
#include "bench/lab/spd_procedure.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "apps/scene/renderer.h"
#include "bench/lab/spd_scenes.h"
#include "bench/lab/spd_suite.h"

namespace rayo {
namespace {

// A scene of the suite at a small image and tile size, so that the image has many tile borders.
SceneDescription small_scene(const std::string& name, int size, int width, int height) {
    SceneDescription d = spd_scene(name, size);
    d.scene.camera.width = width;
    d.scene.camera.height = height;
    d.settings.tile_size = 16;
    return d;
}

TEST(SpdProcedure, CornersTraceEachPixelCornerOnce) {
    // 100 × 70 pixels in 16-pixel tiles: 7 × 5 tiles, the last ones narrower.
    SceneDescription d = small_scene("balls", 1, 100, 70);
    apply_spd_procedure(d.settings);
    const RenderResult corners = render_scene(d, 2, false);
    EXPECT_EQ(corners.counters.camera, 101u * 71u);  // (W + 1) × (H + 1), no more
    // Adaptive at depth 0 averages the same corners but traces those on tile borders once per
    // tile: 7 tiles across trace 100 + 7 columns of corners, 5 down 70 + 5 rows.
    d.settings.aa = AntiAliasing::Adaptive;
    d.settings.adaptive.depth = 0;
    const RenderResult adaptive = render_scene(d, 2, false);
    EXPECT_EQ(adaptive.counters.camera, 107u * 75u);
    // The same image, bit for bit: a corner's value depends only on its place.
    EXPECT_EQ(corners.film.rgba(), adaptive.film.rgba());
    // The children and shadow rays of the duplicates are gone too.
    EXPECT_LT(corners.counters.shadow, adaptive.counters.shadow);
}

TEST(SpdProcedure, CornersDoNotDependOnTheThreadsOrTiles) {
    SceneDescription d = small_scene("gears", 1, 48, 40);
    apply_spd_procedure(d.settings);
    const RenderResult one = render_scene(d, 1, false);
    d.settings.tile_size = 32;
    const RenderResult two = render_scene(d, 2, false);
    EXPECT_EQ(one.counters.camera, 49u * 41u);
    EXPECT_EQ(two.counters.camera, 49u * 41u);
    EXPECT_EQ(one.counters.reflection, two.counters.reflection);
    EXPECT_EQ(one.counters.refraction, two.counters.refraction);
    EXPECT_EQ(one.counters.shadow, two.counters.shadow);
    EXPECT_EQ(one.film.rgba(), two.film.rgba());
}

TEST(SpdProcedure, ReflectionRaysAtTransmittersChangeOnlyTheCounts) {
    // gears' glass has Ks 0: the procedure counts a reflection ray at each of its hits (rule 8),
    // of weight 0, so the image stays the same.
    SceneDescription d = small_scene("gears", 1, 48, 40);
    apply_spd_procedure(d.settings);
    const RenderResult procedure = render_scene(d, 2, false);
    d.settings.whitted().reflect_at_transmitters = false;
    const RenderResult plain = render_scene(d, 2, false);
    EXPECT_GT(procedure.counters.reflection, plain.counters.reflection);
    EXPECT_EQ(procedure.film.rgba(), plain.film.rgba());
}

TEST(SpdProcedure, SettingsFollowTheReadmesRules) {
    RenderSettings s;
    s.aa = AntiAliasing::Adaptive;
    s.whitted().max_depth = 9;
    apply_spd_procedure(s);
    EXPECT_EQ(s.aa, AntiAliasing::Corners);         // rule 6
    EXPECT_EQ(s.whitted().max_depth, 4);            // rule 7: depths 1..5, rayo's 0..4
    EXPECT_EQ(s.whitted().min_contribution, 0.0f);  // rule 8: no adaptive cutoff
    EXPECT_TRUE(s.whitted().reflect_at_transmitters);
    EXPECT_EQ(s.whitted().shadows, ShadowMode::Opaque);
}

TEST(SpdProcedure, CountsAreScaledToTheReadmesCornersAndChecked) {
    RayCounters rays;
    // At 512 pixels the counts are compared as they are.
    rays.camera_hits = 245086;
    rays.reflection = 304643 * 9 / 10 - 1;  // just over 10% low
    rays.refraction = 207564;
    rays.shadow = 2246955 + 2246955 / 20;  // 5% high
    std::vector<SpdCountCheck> checks = check_spd_counts("gears", rays, 512);
    ASSERT_EQ(checks.size(), 4u);
    EXPECT_EQ(checks[0].kind, "eye hit");
    EXPECT_TRUE(checks[0].within());
    EXPECT_DOUBLE_EQ(checks[0].off, 0.0);
    EXPECT_EQ(checks[1].kind, "reflect");
    EXPECT_FALSE(checks[1].within());
    EXPECT_TRUE(checks[2].within());
    EXPECT_NEAR(checks[3].off, 0.05, 1e-6);
    // At 128 pixels (129² corners) each count is scaled by (513 / 129)².
    RayCounters small;
    small.camera_hits = 49788 * 129 * 129 / (513 * 513);
    checks = check_spd_counts("tetra", small, 128);
    EXPECT_NEAR(checks[0].rayo, 49788, 20);
    EXPECT_TRUE(checks[0].within());
    // A kind the Readme counts none of: any ray of it fails.
    small.reflection = 1;
    checks = check_spd_counts("tetra", small, 128);
    EXPECT_FALSE(checks[1].within());
    EXPECT_THROW(check_spd_counts("bunny", small, 128), InputError);
}

TEST(SpdProcedure, FailuresNameTheSceneTheKindAndBothCounts) {
    SuiteRow row;
    row.scene = "mount";
    RayCounters rays;
    rays.camera_hits = 153052;
    rays.reflection = rays.refraction = 354769;
    rays.shadow = 412922;
    row.checks = check_spd_counts("mount", rays, 512);
    const std::vector<std::string> failures = spd_count_failures({row});
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_EQ(failures[0],
              "mount eye hit rays: 153052 against the SPD Readme's 173125 (-11.6%, more than "
              "10% off)");
}

TEST(SpdSuiteJson, HasGoogleBenchmarksShape) {
    SuiteOptions options;
    options.spd_procedure = true;
    options.width = 16;
    options.threads = 1;
    options.repetitions = 2;
    options.only = {"tetra", "balls"};
    std::ostringstream progress;
    const std::vector<SuiteRow> rows = run_spd_suite(options, progress);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].size, spd_default_size("tetra"));
    EXPECT_EQ(rows[0].runs.size(), 2u);
    EXPECT_EQ(rows[0].rays.camera, 17u * 17u);
    const nlohmann::json json = nlohmann::json::parse(suite_json(options, rows, machine_info()));
    const nlohmann::json& context = json.at("context");
    for (const char* key : {"date", "host_name", "executable", "cpu_model", "embree_isa"}) {
        EXPECT_TRUE(context.at(key).is_string()) << key;
    }
    EXPECT_GE(context.at("num_cpus").get<int>(), 1);
    // The device's packet width, and the ISA named from it: at most AVX2's 8 (the device's cap).
    const int packet = context.at("embree_native_packet").get<int>();
    EXPECT_TRUE(packet == 4 || packet == 8) << packet;
    EXPECT_EQ(context.at("embree_isa") == "avx2" || context.at("embree_isa") == "avx", packet == 8);
    EXPECT_EQ(context.at("threads").get<int>(), 1);
    EXPECT_EQ(context.at("procedure"), "spd");
    // Per scene: two iterations, then mean, median, stddev, min and max.
    const nlohmann::json& benchmarks = json.at("benchmarks");
    ASSERT_EQ(benchmarks.size(), 2u * 7u);
    const std::string tetra = "spd/tetra/size:6/width:16";
    const std::vector<std::string> names = {
        tetra,          tetra,         tetra + "_mean", tetra + "_median", tetra + "_stddev",
        tetra + "_min", tetra + "_max"};
    for (size_t i = 0; i < names.size(); ++i) {
        const nlohmann::json& b = benchmarks[i];
        EXPECT_EQ(b.at("name"), names[i]);
        EXPECT_EQ(b.at("run_name"), tetra);
        EXPECT_EQ(b.at("run_type"), i < 2 ? "iteration" : "aggregate");
        EXPECT_EQ(b.at("repetitions").get<int>(), 2);
        EXPECT_EQ(b.at("threads").get<int>(), 1);
        EXPECT_EQ(b.at("time_unit"), "ms");
        EXPECT_TRUE(b.at("real_time").is_number());
        EXPECT_TRUE(b.at("cpu_time").is_number());
        EXPECT_EQ(b.at("camera_rays").get<uint64_t>(), 17u * 17u);
        if (i < 2) EXPECT_EQ(b.at("repetition_index").get<int>(), int(i));
        if (i >= 2) EXPECT_EQ(b.at("aggregate_name"), names[i].substr(tetra.size() + 1));
        if (names[i] != tetra + "_stddev") {
            EXPECT_GT(b.at("rays_per_second").get<double>(), 0.0) << names[i];
            EXPECT_TRUE(b.at("shadow_rays_per_second").is_number());
        }
        EXPECT_EQ(b.at("spd_readme_eye_hit").get<uint64_t>(), 49788u);
    }
    // The median is the middle of the two iterations, min and max their extremes.
    const double a = benchmarks[0].at("real_time"), b = benchmarks[1].at("real_time");
    EXPECT_DOUBLE_EQ(benchmarks[3].at("real_time").get<double>(), 0.5 * (a + b));
    EXPECT_DOUBLE_EQ(benchmarks[5].at("real_time").get<double>(), std::min(a, b));
    EXPECT_DOUBLE_EQ(benchmarks[6].at("real_time").get<double>(), std::max(a, b));
    EXPECT_EQ(benchmarks[7].at("name"), "spd/balls/size:4/width:16");
}

TEST(SpdSuiteJson, WithoutRepetitionsHasNoAggregates) {
    SuiteOptions options;
    options.size = 1;
    options.width = 8;
    options.threads = 1;
    options.only = {"tetra"};
    std::ostringstream progress;
    const std::vector<SuiteRow> rows = run_spd_suite(options, progress);
    const nlohmann::json json = nlohmann::json::parse(suite_json(options, rows, machine_info()));
    ASSERT_EQ(json.at("benchmarks").size(), 1u);
    EXPECT_EQ(json.at("benchmarks")[0].at("name"), "spd/tetra/size:1/width:8");
    EXPECT_EQ(json.at("context").at("procedure"), "none");
    EXPECT_FALSE(json.at("benchmarks")[0].contains("spd_readme_eye_hit"));
}

}  // namespace
}  // namespace rayo
