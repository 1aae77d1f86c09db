// The coherent path (WhittedIntegrator::radiance_coherent, a wavefront over each batch's ray
// tree: the camera rays and their shadow rays as Embree streams, and with stream_secondary every
// depth's rays and shadow rays). Its promise is the single-ray path's image bit for bit, for
// every example scene: opaque and filtered shadows, composite voxels (transmittance
// along shadow rays), fog and absorbing media, area lights of many samples, radiosity, textures.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/scene/default_scene.h"
#include "apps/scene/renderer.h"
#include "apps/scene/scene_loader.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::differing_pixels;
using rayo_test::same_bits;

std::vector<std::string> example_scenes() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(RAYO_SCENES_DIR)) {
        if (entry.path().extension() == ".json") names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

// Renders `d` one ray at a time, then through the coherent path (with the wavefront through
// every depth too when `wavefront`), and expects the same bits and the same ray counts.
void expect_streams_match_single_rays(SceneDescription d, const std::string& name, bool wavefront) {
    d.settings.coherent = false;
    const RenderResult single = render_scene(d, 2, false);
    std::vector<bool> modes = {false};
    if (wavefront) modes.push_back(true);
    for (bool stream_secondary : modes) {
        d.settings.coherent = true;
        // The wavefront is Whitted's; the other integrators' coherent entry is theirs alone.
        if (auto* whitted = std::get_if<WhittedSettings>(&d.settings.integrator)) {
            whitted->stream_secondary = stream_secondary;
        }
        const RenderResult streams = render_scene(d, 2, false);
        const std::string what = name + (stream_secondary ? " (secondary streams)" : "");
        EXPECT_TRUE(same_bits(single.film, streams.film))
            << what << ": " << differing_pixels(single.film, streams.film) << " pixels differ";
        EXPECT_EQ(single.counters.camera, streams.counters.camera) << what;
        EXPECT_EQ(single.counters.shadow, streams.counters.shadow) << what;
        EXPECT_EQ(single.counters.shadow_filtered, streams.counters.shadow_filtered) << what;
        EXPECT_EQ(single.counters.reflection, streams.counters.reflection) << what;
        EXPECT_EQ(single.counters.refraction, streams.counters.refraction) << what;
        EXPECT_EQ(single.counters.total_internal_reflections,
                  streams.counters.total_internal_reflections)
            << what;
        EXPECT_EQ(single.counters.depth_cut, streams.counters.depth_cut) << what;
        EXPECT_EQ(single.counters.contribution_cut, streams.counters.contribution_cut) << what;
    }
}

TEST(StreamPaths, EveryExampleSceneGivesTheSameBitsAsSingleRays) {
    const std::vector<std::string> names = example_scenes();
    ASSERT_GE(names.size(), 20u);
    for (const std::string& name : names) {
        SceneDescription d = load_scene_file(std::string(RAYO_SCENES_DIR) + "/" + name);
        // Small odd sizes: partial tiles and partial stream batches.
        const float aspect = static_cast<float>(d.scene.camera.height) /
                             static_cast<float>(std::max(1, d.scene.camera.width));
        d.scene.camera.width = 53;
        d.scene.camera.height = std::max(1, static_cast<int>(53.0f * aspect));
        d.settings.spp = std::min(d.settings.spp, 2);
        expect_streams_match_single_rays(d, name, false);
    }
}

// The path integrator's wavefront (PathIntegrator::radiance_coherent: every round of bounce
// rays and their shadow rays as streams) against its single rays, on every example scene.
TEST(StreamPaths, PathTracingGivesTheSameBitsAsSingleRays) {
    for (const std::string& name : example_scenes()) {
        SceneDescription d = load_scene_file(std::string(RAYO_SCENES_DIR) + "/" + name);
        const float aspect = static_cast<float>(d.scene.camera.height) /
                             static_cast<float>(std::max(1, d.scene.camera.width));
        d.scene.camera.width = 37;
        d.scene.camera.height = std::max(1, static_cast<int>(37.0f * aspect));
        d.settings.spp = 2;
        d.settings.integrator = PathSettings{};
        expect_streams_match_single_rays(d, name + " (path)", false);
    }
}

// Deep ray trees: the default scene's glass and mirror spheres at every depth limit, with
// filtered shadows (the shadow rays through glass go on ray by ray) and without, also through
// the wavefront of stream_secondary: its analytic spheres run rayo's own kernels, the same
// arithmetic lane by lane (with triangles that is not so: whitted.h).
TEST(StreamPaths, DeepRayTreesGiveTheSameBitsAsSingleRays) {
    SceneDescription d = make_default_scene();
    d.scene.camera.width = 67;
    d.scene.camera.height = 45;
    for (int depth : {0, 1, 3, 8}) {
        for (ShadowMode shadows : {ShadowMode::Opaque, ShadowMode::Filtered}) {
            d.settings.whitted().max_depth = depth;
            d.settings.whitted().shadows = shadows;
            expect_streams_match_single_rays(
                d,
                "depth " + std::to_string(depth) +
                    (shadows == ShadowMode::Filtered ? " filtered" : " opaque"),
                true);
        }
    }
}

}  // namespace
}  // namespace rayo
