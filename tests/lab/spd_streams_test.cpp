// The SPD scenes (bench/lab/spd_scenes.h) through the coherent path (camera rays and their
// shadow rays as Embree streams, the wavefront of WhittedIntegrator::radiance_coherent) against
// the single-ray path: the same bits. gears and mount carry the hard cases: glass (refraction
// at every depth) and the overlapping coplanar triangles of the gears' concave faces, where a
// closest-hit query's answer depends on the traversal order.
#include <gtest/gtest.h>

#include "apps/scene/renderer.h"
#include "bench/lab/spd_scenes.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::differing_pixels;
using rayo_test::same_bits;

TEST(SpdStreams, EverySpdSceneGivesTheSameBitsAsSingleRays) {
    for (const std::string& name : spd_scene_names()) {
        SceneDescription d = spd_scene(name, 2);
        d.scene.camera.width = 96;
        d.scene.camera.height = 96;
        d.settings.coherent = false;
        const RenderResult single = render_scene(d, 2, false);
        d.settings.coherent = true;
        const RenderResult streams = render_scene(d, 2, false);
        EXPECT_TRUE(same_bits(single.film, streams.film))
            << name << ": " << differing_pixels(single.film, streams.film) << " pixels differ";
        EXPECT_EQ(single.counters.total_rays(), streams.counters.total_rays()) << name;
    }
}

}  // namespace
}  // namespace rayo
