// Image-level tests of the seed 004 camera extensions and of adaptive antialiasing through the
// whole render path: depth of field against the thin-lens circle of confusion, fisheye and
// panorama pixels of known directions, and adaptive antialiasing's determinism and accuracy.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/scene/renderer.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::same_bits;

// Objects of constant radiance 1 (ambient only) on a black background: a pixel's value is the
// share of its samples that hit an object. The camera at z = 10 looks at the origin.
SceneDescription emitter_scene(int size, float vfov_degrees) {
    SceneDescription d;
    d.source = "<camera test>";
    d.scene.camera.eye = Vec3(0, 0, 10);
    d.scene.camera.look_at = Vec3(0);
    d.scene.camera.vfov_degrees = vfov_degrees;
    d.scene.camera.width = size;
    d.scene.camera.height = size;
    Material m;
    m.ka = Vec3(1.0f);
    m.kd = Vec3(0.0f);
    d.shading.materials.push_back(m);
    d.shading.ambient_light = Vec3(1.0f);
    d.shading.background = Vec3(0.0f);
    return d;
}

double film_sum(const Film& film) {
    double sum = 0.0;
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) sum += film.rgb(x, y).x;
    }
    return sum;
}

// ---- Thin lens ---------------------------------------------------------------------------------

TEST(RenderDepthOfField, ADiskOnTheFocalPlaneStaysSharp) {
    // A disk lying in the plane in focus, facing the camera: every lens sample of a film
    // position meets the plane at the same point, so the image is the pinhole's.
    SceneDescription d = emitter_scene(96, 20.0f);
    d.scene.shapes.of<Disk>().push_back({Vec3(0), Vec3(0, 0, 1), 1.0f, 0});
    d.settings.spp = 16;
    const RenderResult pinhole = render_scene(d, 0, false);
    d.scene.camera.lens_radius = 0.5f;
    const RenderResult lens = render_scene(d, 0, false);
    int differing = 0;
    float largest = 0.0f;
    for (int y = 0; y < 96; ++y) {
        for (int x = 0; x < 96; ++x) {
            const float difference = std::abs(lens.film.rgb(x, y).x - pinhole.film.rgb(x, y).x);
            differing += difference > 0.0f;
            largest = std::max(largest, difference);
        }
    }
    // Float rounding can move a sample that grazes the rim across it: one sample in 16.
    EXPECT_LE(differing, 3);
    EXPECT_LE(largest, 1.0f / 16.0f);
    // Moved off the focal plane (to depth 7), the same disk's rim blurs over many pixels.
    d.scene.shapes.of<Disk>()[0].center = Vec3(0, 0, 3);
    const RenderResult blurred = render_scene(d, 0, false);
    int partial = 0;
    for (int y = 0; y < 96; ++y) {
        for (int x = 0; x < 96; ++x) {
            const float v = blurred.film.rgb(x, y).x;
            partial += v > 0.1f && v < 0.9f;
        }
    }
    EXPECT_GT(partial, 300);
}

TEST(RenderDepthOfField, SmallSphereOffThePlaneImagesAsTheCircleOfConfusion) {
    // Thin lens of radius A focused at F = 10 (the look-at distance); a sphere of radius ρ at
    // depth z = 5. A point at depth z spreads over a disk of radius A·|z − F|/z on the focal
    // plane (similar triangles through the lens rim), and the sphere's image (radius ρ·F/z) is
    // convolved with it: the value is the share of the lens that sees the sphere, a plateau of
    // (ρF/|F − z|)²/A² in the middle. The sum over the image is the sphere's pinhole image area
    // π(ρF/z)², so sum / plateau = π·(A·|z − F|/z)², the circle of confusion's area.
    constexpr int kSize = 128;
    constexpr float kVfov = 20.0f, A = 0.5f, F = 10.0f, z = 5.0f, rho = 0.15f;
    SceneDescription d = emitter_scene(kSize, kVfov);
    d.scene.camera.lens_radius = A;
    d.scene.shapes.of<Sphere>().push_back({Vec3(0, 0, F - z), rho, 0});
    d.settings.spp = 256;
    const RenderResult r = render_scene(d, 0, false);

    const double pixel_at_focus = 2.0 * F * std::tan(kVfov * kPi / 360.0) / kSize;
    const double coc_px = A * std::abs(z - F) / z / pixel_at_focus;  // radius, pixels
    const double image_px = rho * F / z / pixel_at_focus;
    const double expected_plateau = std::pow(rho * F / std::abs(F - z) / A, 2.0);
    // The plateau: pixels well inside radius coc − image of the centre (63.5, 63.5).
    double plateau = 0.0;
    int count = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (std::hypot(x - 63.5, y - 63.5) < coc_px - image_px - 1.0) {
                plateau += r.film.rgb(x, y).x;
                ++count;
            }
        }
    }
    ASSERT_GT(count, 50);
    plateau /= count;
    EXPECT_NEAR(plateau, expected_plateau, 0.03 * expected_plateau);
    const double diameter = 2.0 * std::sqrt(film_sum(r.film) / plateau / kPi);
    EXPECT_NEAR(diameter, 2.0 * coc_px, 0.05 * 2.0 * coc_px)
        << "expected the circle of confusion, " << 2.0 * coc_px << " pixels";
    // Without the lens the sphere is a sharp disk of the pinhole image's size.
    d.scene.camera.lens_radius = 0.0f;
    const RenderResult sharp = render_scene(d, 0, false);
    EXPECT_NEAR(film_sum(sharp.film), kPi * image_px * image_px, 0.02 * kPi * image_px * image_px);
}

// ---- Fisheye and panorama ----------------------------------------------------------------------

TEST(RenderFisheye, OutsideTheImageCircleIsTransparentBackground) {
    SceneDescription d = emitter_scene(64, 45.0f);
    d.scene.camera.vfov_degrees.reset();
    d.scene.camera.projection = Projection::Fisheye;
    d.scene.camera.width = 96;  // the circle is inscribed in the height: radius 32
    d.shading.background = Vec3(0.25f);
    const RenderResult r = render_scene(d, 0, false);
    int inside = 0;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 96; ++x) {
            const float* p = &r.film.rgba()[(size_t(y) * 96 + x) * 4];
            const double radius = std::hypot(x - 47.5, y - 31.5);
            if (radius < 31.5) {
                EXPECT_EQ(p[3], 1.0f) << x << ", " << y;
                EXPECT_EQ(p[0], 0.25f);  // the background, seen through the lens
                ++inside;
            } else if (radius > 32.5) {
                EXPECT_EQ(p[3], 0.0f) << x << ", " << y;
                EXPECT_EQ(p[0], 0.0f);
            }
        }
    }
    EXPECT_GT(inside, 3000);
    EXPECT_LT(r.counters.camera, 96u * 64u);  // no camera ray outside the circle
}

// The pixel where a small emitter in direction `direction` from the eye appears: the centroid of
// the lit pixels.
glm::dvec2 centroid_of(SceneDescription d, const Vec3& direction) {
    d.scene.shapes.of<Sphere>().push_back(
        {d.scene.camera.eye + 20.0f * glm::normalize(direction), 0.4f, 0});
    const RenderResult r = render_scene(d, 0, false);
    glm::dvec2 sum(0.0);
    double weight = 0.0;
    for (int y = 0; y < r.film.height(); ++y) {
        for (int x = 0; x < r.film.width(); ++x) {
            const double v = r.film.rgb(x, y).x;
            sum += v * glm::dvec2(x, y);
            weight += v;
        }
    }
    EXPECT_GT(weight, 0.0);
    return sum / weight;
}

// The emitter in `direction` appears centred on pixel (x, y), within 0.3 pixels.
void expect_at(const SceneDescription& d, const Vec3& direction, double x, double y) {
    const glm::dvec2 c = centroid_of(d, direction);
    EXPECT_NEAR(c.x, x, 0.3) << direction.x << " " << direction.y << " " << direction.z;
    EXPECT_NEAR(c.y, y, 0.3) << direction.x << " " << direction.y << " " << direction.z;
}

TEST(RenderFisheye, KnownDirectionsLandOnKnownPixels) {
    // 180° fisheye, 129 × 129: the centre pixel (64, 64) looks along −z; 90° off the axis is the
    // rim, 64.5 pixels out; 45° is half-way.
    SceneDescription d = emitter_scene(129, 45.0f);
    d.scene.camera.vfov_degrees.reset();
    d.scene.camera.projection = Projection::Fisheye;
    expect_at(d, Vec3(0, 0, -1), 64.0, 64.0);
    expect_at(d, Vec3(1, 0, -1), 64.0 + 32.25, 64.0);  // 45° right
    expect_at(d, Vec3(0, 1, -1), 64.0, 64.0 - 32.25);  // 45° up: toward row 0
    expect_at(d, Vec3(-1, 0, -0.3639702f), 64.0 - 64.5 * 70.0 / 90.0, 64.0);  // 70° left
}

TEST(RenderPanorama, KnownDirectionsLandOnKnownPixels) {
    // 256 × 128 equirectangular: 1.40625° per pixel; longitude 0 (−z) at x = 127.5, +90° (+x)
    // at 191.5, 180° behind at the edges; latitude 0 at y = 63.5, +45° at 31.5.
    SceneDescription d = emitter_scene(128, 45.0f);
    d.scene.camera.vfov_degrees.reset();
    d.scene.camera.projection = Projection::Spherical;
    d.scene.camera.width = 256;
    expect_at(d, Vec3(0, 0, -1), 127.5, 63.5);
    expect_at(d, Vec3(1, 0, 0), 191.5, 63.5);
    expect_at(d, Vec3(-1, 0, 0), 63.5, 63.5);
    expect_at(d, Vec3(0, 1, -1), 127.5, 31.5);
    expect_at(d, Vec3(1, std::sqrt(2.0f), -1), 159.5, 31.5);  // longitude +45°, latitude +45°
}

// ---- Adaptive antialiasing ---------------------------------------------------------------------

SceneDescription adaptive_scene() {
    SceneDescription d = emitter_scene(80, 20.0f);
    d.scene.camera.width = 112;
    d.scene.shapes.of<Sphere>().push_back({Vec3(0.3f, 0.1f, 0), 1.1f, 0});
    d.scene.shapes.of<Disk>().push_back({Vec3(-1.2f, -0.5f, 1), Vec3(0, 0, 1), 0.5f, 0});
    d.settings.aa = AntiAliasing::Adaptive;
    d.settings.adaptive.threshold = 0.1f;
    d.settings.adaptive.depth = 3;
    return d;
}

TEST(RenderAdaptive, SameBitsForAnyThreadCountAndTileSize) {
    SceneDescription d = adaptive_scene();
    d.settings.tile_size = 16;
    const RenderResult reference = render_scene(d, 1, false);
    for (int threads : {2, 5}) {
        for (int tile : {32, 48, 128}) {
            d.settings.tile_size = tile;
            const RenderResult r = render_scene(d, threads, false);
            EXPECT_TRUE(same_bits(reference.film, r.film))
                << "threads " << threads << " tile " << tile;
        }
    }
}

TEST(RenderAdaptive, EvenImageTracesOnlyThePixelCorners) {
    // Nothing in view: every corner agrees, nothing is subdivided. One tile: each of the
    // (w + 1)(h + 1) corners traced once.
    SceneDescription d = adaptive_scene();
    d.scene.shapes.of<Sphere>().clear();
    d.scene.shapes.of<Disk>().clear();
    d.settings.tile_size = 128;
    const RenderResult r = render_scene(d, 1, false);
    EXPECT_EQ(r.counters.camera, 113u * 81u);
}

TEST(RenderAdaptive, EdgesAreRefinedToTheCoverageOfThePixels) {
    // A sharp-edged scene: pixel values are coverages. Adaptive antialiasing at depth 4 finds the
    // objects' projected area (within a small fraction of the rim) and comes closer to a 1024-spp
    // reference than one sample per pixel, with far fewer rays than the full 16 × 16 lattice.
    SceneDescription d = adaptive_scene();
    d.settings.aa = AntiAliasing::Stratified;
    d.settings.spp = 1024;
    const Film reference = render_scene(d, 0, false).film;
    d.settings.spp = 1;
    const Film single = render_scene(d, 0, false).film;
    d.settings.aa = AntiAliasing::Adaptive;
    d.settings.adaptive.depth = 4;
    const RenderResult adaptive = render_scene(d, 0, false);
    const auto rms = [&](const Film& film) {
        double sum = 0.0;
        for (int y = 0; y < film.height(); ++y) {
            for (int x = 0; x < film.width(); ++x) {
                sum += std::pow(film.rgb(x, y).x - reference.rgb(x, y).x, 2.0);
            }
        }
        return std::sqrt(sum / (film.width() * film.height()));
    };
    EXPECT_LT(rms(adaptive.film), 0.25 * rms(single));
    EXPECT_NEAR(film_sum(adaptive.film), film_sum(reference), 0.005 * film_sum(reference));
    EXPECT_LT(adaptive.counters.camera, 112u * 80u * 16u);  // well below 256 rays per pixel
    EXPECT_GT(adaptive.counters.camera, 113u * 81u);        // but it did subdivide
}

TEST(RenderAdaptive, ThresholdAboveEveryDifferenceNeverSubdivides) {
    // Corner differences here are at most 1 per channel (4 in all): with a threshold of 4 no
    // square is split, every pixel is the mean of its four corners (a multiple of 1/4), and one
    // tile traces each corner once. Just below 4 nothing changes either; at 0.5 the edges split.
    SceneDescription d = adaptive_scene();
    d.settings.tile_size = 128;
    d.settings.adaptive.threshold = 4.0f;
    const RenderResult r = render_scene(d, 1, false);
    EXPECT_EQ(r.counters.camera, 113u * 81u);
    for (int y = 0; y < 80; ++y) {
        for (int x = 0; x < 112; ++x) {
            const float v = r.film.rgb(x, y).x * 4.0f;
            EXPECT_EQ(v, std::round(v)) << x << ", " << y;
        }
    }
    d.settings.adaptive.threshold = 0.5f;
    EXPECT_GT(render_scene(d, 1, false).counters.camera, 113u * 81u);
}

}  // namespace
}  // namespace rayo
