// Image-level tests of the whole render path (Accel + Whitted + tile loop) against closed forms,
// and the determinism promise: identical bits for any thread count and tile size.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/scene/default_scene.h"
#include "apps/scene/renderer.h"
#include "core/error.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::same_bits;

// A unit Lambert sphere seen from far away, lit by a directional light travelling along the
// view direction: each visible point has radiance kd·I·(n·L), and over the projected disk the
// mean of n·L = √(1 − r²) is ∫₀¹ √(1−r²)·2r dr = 2/3. So the disk's mean pixel is kd·I·2/3.
SceneDescription lambert_sphere_scene(int size) {
    SceneDescription d;
    d.source = "<lambert test>";
    d.scene.camera.eye = Vec3(0, 0, 1000);
    d.scene.camera.look_at = Vec3(0);
    d.scene.camera.vfov_degrees = 2.0f * glm::degrees(std::atan(1.05f / 1000.0f));
    d.scene.camera.width = size;
    d.scene.camera.height = size;
    Material m;
    m.ka = Vec3(0.0f);
    m.kd = Vec3(0.7f, 0.5f, 0.3f);
    d.shading.materials.push_back(m);
    d.scene.shapes.of<Sphere>().push_back({Vec3(0), 1.0f, 0});
    DirectionalLight light;
    light.direction = Vec3(0, 0, -1);
    light.intensity = 2.0f;
    d.shading.lights.push_back(light);
    d.shading.background = Vec3(0.0f);
    return d;
}

TEST(RenderClosedForm, LambertSphereDiskMeanIsTwoThirdsOfKdTimesI) {
    const SceneDescription d = lambert_sphere_scene(400);
    const RenderResult r = render_scene(d, 0, false);
    Vec3 sum(0.0f);
    int count = 0;
    for (int y = 0; y < r.film.height(); ++y) {
        for (int x = 0; x < r.film.width(); ++x) {
            const Vec3 c = r.film.rgb(x, y);
            if (c.x > 0.0f) {
                sum += c;
                ++count;
            }
        }
    }
    ASSERT_GT(count, 1000);
    const Vec3 mean = sum / static_cast<float>(count);
    const Vec3 expected = Vec3(0.7f, 0.5f, 0.3f) * 2.0f * (2.0f / 3.0f);
    // Pixel-centre sampling of the disk: the rim pixels make an error of O(1/size).
    EXPECT_NEAR(mean.x, expected.x, 0.01f * expected.x);
    EXPECT_NEAR(mean.y, expected.y, 0.01f * expected.y);
    EXPECT_NEAR(mean.z, expected.z, 0.01f * expected.z);
    // The disk covers π r² of the (2.1 r)² window.
    const float coverage = static_cast<float>(count) / (400.0f * 400.0f);
    EXPECT_NEAR(coverage, kPi / (2.1f * 2.1f), 0.01f);
    EXPECT_EQ(r.counters.camera, 400u * 400u);
    EXPECT_EQ(r.counters.shadow, static_cast<uint64_t>(count));
}

TEST(RenderClosedForm, CentrePixelSeesFullIrradiance) {
    const SceneDescription d = lambert_sphere_scene(101);
    const RenderResult r = render_scene(d, 1, false);
    const Vec3 centre = r.film.rgb(50, 50);
    EXPECT_NEAR(centre.x, 0.7f * 2.0f, 1e-4f);
    EXPECT_EQ(r.film.rgb(0, 0), Vec3(0.0f));  // corner: background
}

TEST(RenderOrientation, ObjectRightOfViewAxisLandsInRightHalf) {
    SceneDescription d = lambert_sphere_scene(64);
    d.scene.camera.eye = Vec3(0, 0, 10);
    d.scene.camera.vfov_degrees = 60.0f;
    d.scene.shapes.of<Sphere>()[0] = {Vec3(3, 2, 0), 0.5f, 0};  // +x right, +y up for this camera
    const RenderResult r = render_scene(d, 0, false);
    int left = 0, right = 0, top = 0, bottom = 0;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            if (r.film.rgb(x, y).x <= 0.0f) continue;
            (x < 32 ? left : right)++;
            (y < 32 ? top : bottom)++;
        }
    }
    EXPECT_GT(right, 0);
    EXPECT_EQ(left, 0);
    EXPECT_GT(top, 0);  // row 0 is the top of the image
    EXPECT_EQ(bottom, 0);
}

TEST(RenderDeterminism, SameBitsForAnyThreadCountAndTileSize) {
    SceneDescription d = make_default_scene();
    d.scene.camera.width = 120;
    d.scene.camera.height = 90;
    d.settings.spp = 4;
    d.settings.tile_size = 16;
    const RenderResult reference = render_scene(d, 1, false);
    for (int threads : {2, 3, 8}) {
        for (int tile : {16, 32, 48, 64, 128}) {
            d.settings.tile_size = tile;
            const RenderResult r = render_scene(d, threads, false);
            EXPECT_TRUE(same_bits(reference.film, r.film))
                << "threads " << threads << " tile " << tile;
            EXPECT_EQ(r.counters.total_rays(), reference.counters.total_rays());
        }
    }
}

// Triangle scenes too: where coplanar triangles overlap (the fan of a concave polygon, as in
// the SPD gears), which one Embree reports depends on the traversal, and its packet traversal
// differs from single rays. So the coherent batches follow the image's 16×16 blocks, never the
// tile: with batches cut by the tile, 10 pixels of gears changed between tile sizes 16 and 64.
TEST(RenderDeterminism, OverlappingTrianglesGiveTheSameBitsForAnyTileSize) {
    SceneDescription d;
    d.source = "<overlap>";
    d.scene.camera.eye = Vec3(0.3f, 0.2f, 3.0f);
    d.scene.camera.look_at = Vec3(0.0f);
    d.scene.camera.vfov_degrees = 50.0f;
    d.scene.camera.width = 160;
    d.scene.camera.height = 144;
    for (const Vec3& colour : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}) {
        Material m;
        m.kd = colour;
        d.shading.materials.push_back(m);
    }
    // Many coplanar triangles in z = 0, each overlapping its neighbours, alternating materials.
    TriangleMesh mesh;
    for (int i = 0; i < 24; ++i) {
        const float a = 0.2618f * static_cast<float>(i);
        const auto base = static_cast<uint32_t>(mesh.positions.size());
        mesh.positions.push_back(Vec3(0.0f));
        mesh.positions.push_back(Vec3(std::cos(a), std::sin(a), 0.0f));
        mesh.positions.push_back(Vec3(std::cos(a + 0.9f), std::sin(a + 0.9f), 0.0f));
        mesh.triangles.push_back({base, base + 1, base + 2});
        mesh.materials.push_back(static_cast<uint32_t>(i % 3));
    }
    d.scene.meshes.push_back(mesh);
    PointLight light;
    light.position = Vec3(1, 2, 4);
    d.shading.lights.push_back(light);
    d.settings.spp = 2;
    d.settings.tile_size = 16;
    const RenderResult reference = render_scene(d, 1, false);
    for (int tile : {32, 64, 128}) {
        d.settings.tile_size = tile;
        EXPECT_TRUE(same_bits(reference.film, render_scene(d, 2, false).film)) << "tile " << tile;
    }
}

// The coherent path (Embree streams for a tile's camera and shadow rays) must give the same bits
// as tracing ray by ray, for every sphere method, with antialiasing and tiles cut by the image.
TEST(RenderDeterminism, CoherentStreamsGiveTheSameBitsAsSingleRays) {
    SceneDescription d = make_default_scene();
    d.scene.camera.width = 97;
    d.scene.camera.height = 61;
    d.settings.spp = 2;
    for (const char* method : {"user", "bruteforce", "embree-point", "mesh:2"}) {
        d.settings.spheres = *parse_sphere_method(method);
        for (int tile : {16, 48}) {
            d.settings.tile_size = tile;
            d.settings.coherent = false;
            const RenderResult single = render_scene(d, 2, false);
            d.settings.coherent = true;
            const RenderResult coherent = render_scene(d, 2, false);
            EXPECT_TRUE(same_bits(single.film, coherent.film)) << method << " tile " << tile;
            // Embree's own sphere kernel rounds differently in packets: it stays on single rays.
            EXPECT_EQ(coherent.coherent, std::string(method) != "embree-point") << method;
            EXPECT_EQ(single.counters.total_rays(), coherent.counters.total_rays()) << method;
            EXPECT_EQ(single.counters.shadow, coherent.counters.shadow) << method;
        }
    }
}

TEST(RenderDefaultScene, ExercisesShadowsReflectionAndRefraction) {
    SceneDescription d = make_default_scene();
    d.scene.camera.width = 160;
    d.scene.camera.height = 120;
    const RenderResult r = render_scene(d, 0, false);
    EXPECT_EQ(r.counters.camera, 160u * 120u);
    EXPECT_GT(r.counters.shadow, 0u);
    EXPECT_GT(r.counters.reflection, 0u);
    EXPECT_GT(r.counters.refraction, 0u);
    for (float v : r.film.rgba()) ASSERT_TRUE(std::isfinite(v));
}

// A right-angle glass prism (cross-section (-1, 1), (1, 1), (1, -1) in xz, y in [-2, 2]) seen
// head-on through its z = 1 face by a narrow camera on the z axis, and an ambient-lit target
// (x = 3, |y| <= 3, |z| <= 1.5) facing its x = 1 face. A camera ray enters almost along the face
// normal and meets the hypotenuse x + z = 0 at 45° ± 1.9° (4° field of view: at most 2.83° off
// axis outside, 1.89° inside for n = 1.5). For n = 1.5 the critical angle is asin(1/1.5) =
// 41.8°, so every ray is totally reflected to +x, leaves through the x = 1 face near normal
// incidence and sees the target. For n = 1.3 (critical 50.3°) every ray leaves through the
// hypotenuse instead, along about (0.37, 0, -0.93) (Snell: 1.3·sin 45° = sin 66.8°), and passes
// the target's plane at z < -5: it sees the background.
SceneDescription prism_scene(float ior, const Vec3& target_colour, const Vec3& background) {
    SceneDescription d;
    d.source = "<tir test>";
    d.scene.camera.eye = Vec3(0, 0, 20);
    d.scene.camera.look_at = Vec3(0);
    d.scene.camera.vfov_degrees = 4.0f;
    d.scene.camera.width = 24;
    d.scene.camera.height = 24;
    Material glass;  // no local colour, no mirror term: only the transmitted weight 0.8
    glass.ka = glass.kd = glass.ks = Vec3(0.0f);
    glass.transmit = Vec3(0.8f);
    glass.ior = ior;
    d.shading.materials.push_back(glass);
    Material target;  // ambient only: its radiance is ka·Ia = target_colour everywhere
    target.ka = target_colour;
    target.kd = target.ks = Vec3(0.0f);
    d.shading.materials.push_back(target);
    const auto a = [](float y) { return Vec3(-1, y, 1); };
    const auto b = [](float y) { return Vec3(1, y, 1); };
    const auto c = [](float y) { return Vec3(1, y, -1); };
    TriangleMesh prism;  // counter-clockwise seen from outside: outward normals
    EXPECT_TRUE(prism.add_convex_polygon({a(-2), b(-2), b(2), a(2)}, {}, 0));  // z = 1, +z
    EXPECT_TRUE(prism.add_convex_polygon({b(-2), c(-2), c(2), b(2)}, {}, 0));  // x = 1, +x
    EXPECT_TRUE(prism.add_convex_polygon({a(-2), a(2), c(2), c(-2)}, {}, 0));  // hypotenuse
    EXPECT_TRUE(prism.add_convex_polygon({a(-2), c(-2), b(-2)}, {}, 0));       // y = -2
    EXPECT_TRUE(prism.add_convex_polygon({a(2), b(2), c(2)}, {}, 0));          // y = 2
    d.scene.meshes.push_back(prism);
    TriangleMesh plane;
    EXPECT_TRUE(plane.add_convex_polygon(
        {Vec3(3, -3, -1.5f), Vec3(3, -3, 1.5f), Vec3(3, 3, 1.5f), Vec3(3, 3, -1.5f)}, {}, 1));
    d.scene.meshes.push_back(plane);
    d.shading.ambient_light = Vec3(1.0f);
    d.shading.background = background;
    return d;
}

// Pixels with a channel more than 1e-6 from `expected`.
int pixels_off(const Film& film, const Vec3& expected) {
    int off = 0;
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            const Vec3 d = glm::abs(film.rgb(x, y) - expected);
            off += !(glm::max(d.x, glm::max(d.y, d.z)) <= 1e-6f);
        }
    }
    return off;
}

// Whitted's rule (shading/integrators/whitted.cpp): total internal reflection sends the transmitted
// weight into the reflected ray. Each pixel is then transmit (in) × transmit (TIR) × transmit (out)
// × the target, 0.8³·target, with exactly one TIR, one reflection and two refractions per pixel.
// Without TIR (n = 1.3) the same path gives 0.8²·background and no TIR at all.
TEST(RenderTransport, PrismTotallyReflectsWithTheTransmittedWeight) {
    const Vec3 target(0.25f, 0.5f, 1.0f), background(0.1f, 0.2f, 0.3f);
    const uint64_t pixels = 24 * 24;
    const RenderResult tir = render_scene(prism_scene(1.5f, target, background), 0, false);
    EXPECT_EQ(tir.counters.total_internal_reflections, pixels);
    EXPECT_EQ(tir.counters.reflection, pixels);
    EXPECT_EQ(tir.counters.refraction, 2 * pixels);
    EXPECT_EQ(pixels_off(tir.film, 0.512f * target), 0);
    rayo_test::expect_vec_near(tir.film.rgb(12, 12), 0.512f * target, 1e-6);
    const RenderResult no_tir = render_scene(prism_scene(1.3f, target, background), 0, false);
    EXPECT_EQ(no_tir.counters.total_internal_reflections, 0u);
    EXPECT_EQ(no_tir.counters.reflection, 0u);
    EXPECT_EQ(no_tir.counters.refraction, 2 * pixels);
    EXPECT_EQ(pixels_off(no_tir.film, 0.64f * background), 0);
    rayo_test::expect_vec_near(no_tir.film.rgb(12, 12), 0.64f * background, 1e-6);
}

TEST(RenderDepth, MaxDepthZeroTracesNoSecondaryRays) {
    SceneDescription d = make_default_scene();
    d.scene.camera.width = 64;
    d.scene.camera.height = 48;
    d.settings.whitted().max_depth = 0;
    const RenderResult r = render_scene(d, 0, false);
    EXPECT_EQ(r.counters.reflection, 0u);
    EXPECT_EQ(r.counters.refraction, 0u);
    EXPECT_GT(r.counters.depth_cut, 0u);
}

}  // namespace
}  // namespace rayo

namespace rayo {
namespace {

TEST(RenderValidation, MaterialIdPastTheTableIsAnInputError) {
    SceneDescription d = lambert_sphere_scene(8);
    d.scene.shapes.of<Sphere>()[0].material = 3;
    EXPECT_THROW(render_scene(d, 1, false), InputError);
    d.scene.shapes.of<Sphere>()[0].material = 0;
    TriangleMesh mesh;
    mesh.add_convex_polygon({Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {}, 0);
    mesh.materials[0] = 9;
    d.scene.meshes.push_back(mesh);
    EXPECT_THROW(render_scene(d, 1, false), InputError);
}

TEST(RenderValidation, TextureIdPastTheTableIsAnInputError) {
    SceneDescription d = lambert_sphere_scene(8);
    d.shading.materials[0].textures.kd = 2;  // no textures defined
    EXPECT_THROW(render_scene(d, 1, false), InputError);
    d.shading.materials[0].textures.kd = kNoTexture;
    EXPECT_NO_THROW(render_scene(d, 1, false));
}

}  // namespace
}  // namespace rayo
