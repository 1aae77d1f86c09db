// Tests of the preview (apps/scene/preview.h): lines alone on black, lines over the darkened
// 1 spp render, and the drawn sphere outline against the silhouette the renderer draws.
#include "apps/scene/preview.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "apps/scene/renderer.h"
#include "core/error.h"

namespace rayo {
namespace {

// An off-centre sphere lit only by ambient light on black: every pixel whose ray hits it is
// non-zero, every other pixel black.
SceneDescription sphere_scene() {
    SceneDescription d;
    d.source = "<preview test>";
    d.scene.camera.eye = Vec3(0, 0, 6);
    d.scene.camera.look_at = Vec3(0);
    d.scene.camera.hfov_degrees = 45.0f;
    d.scene.camera.width = 120;
    d.scene.camera.height = 90;
    Material m;
    m.ka = Vec3(0.5f);
    m.kd = Vec3(0.0f);
    m.ks = Vec3(0.0f);
    d.shading.materials.push_back(m);
    d.shading.ambient_light = Vec3(1.0f);
    d.scene.shapes.of<Sphere>().push_back({Vec3(0.9f, 0.4f, -0.5f), 0.9f, 0});
    d.shading.background = Vec3(0.0f);
    return d;
}

bool is_line(const Film& film, int x, int y, const Vec3& line) {
    return film.rgb(x, y) == line;
}

TEST(Preview, LinesAloneAreOnOpaqueBlack) {
    const SceneDescription d = sphere_scene();
    PreviewOptions options;
    const PreviewResult r = render_preview(d, options);
    ASSERT_EQ(r.film.width(), 120);
    ASSERT_EQ(r.film.height(), 90);
    int lines = 0;
    for (int y = 0; y < 90; ++y) {
        for (int x = 0; x < 120; ++x) {
            const float* p = &r.film.rgba()[(static_cast<size_t>(y) * 120 + x) * 4];
            EXPECT_EQ(p[3], 1.0f);
            if (is_line(r.film, x, y, options.line_rgb)) {
                ++lines;
            } else {
                EXPECT_EQ(p[0] + p[1] + p[2], 0.0f) << x << "," << y;
            }
        }
    }
    EXPECT_GT(lines, 100);
    EXPECT_EQ(r.stats.objects, 1u);
    EXPECT_EQ(r.stats.drawn, r.stats.segments);
    EXPECT_EQ(r.render_seconds, 0.0);
}

TEST(Preview, OverRenderIsTheOneSampleRenderDarkenedUnderTheLines) {
    SceneDescription d = sphere_scene();
    d.settings.spp = 16;  // the preview renders 1 spp whatever the scene asks
    PreviewOptions options;
    options.over_render = true;
    const PreviewResult r = render_preview(d, options);
    d.settings.spp = 1;
    const RenderResult render = render_scene(d, 0, false);
    int under = 0;
    for (int y = 0; y < 90; ++y) {
        for (int x = 0; x < 120; ++x) {
            if (is_line(r.film, x, y, options.line_rgb)) continue;
            EXPECT_EQ(r.film.rgb(x, y), render.film.rgb(x, y) * options.render_gain)
                << x << "," << y;
            under += render.film.rgb(x, y).x > 0.0f;
        }
    }
    EXPECT_GT(under, 500);  // the sphere shows under the lines
}

TEST(Preview, SphereOutlineIsWithinAPixelOfTheRenderedSilhouette) {
    const SceneDescription d = sphere_scene();
    const RenderResult render = render_scene(d, 0, false);
    const PreviewResult preview = render_preview(d, PreviewOptions{});
    const int w = 120, h = 90;
    const auto hit = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && render.film.rgb(x, y).x > 0.0f;
    };
    const Vec3 line_rgb = PreviewOptions{}.line_rgb;
    const auto line = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && preview.film.rgb(x, y) == line_rgb;
    };
    // Is there a pixel of `set` in the 3×3 neighbourhood of (x, y)?
    const auto near = [](const auto& set, int x, int y) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                if (set(x + dx, y + dy)) return true;
            }
        }
        return false;
    };
    const auto silhouette = [&](int x, int y) {
        return hit(x, y) && (!hit(x - 1, y) || !hit(x + 1, y) || !hit(x, y - 1) || !hit(x, y + 1));
    };
    int silhouette_pixels = 0, line_pixels = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (silhouette(x, y)) {
                ++silhouette_pixels;
                EXPECT_TRUE(near(line, x, y)) << "silhouette pixel " << x << "," << y;
            }
            if (line(x, y)) {
                ++line_pixels;
                EXPECT_TRUE(near(silhouette, x, y)) << "outline pixel " << x << "," << y;
            }
        }
    }
    EXPECT_GT(silhouette_pixels, 60);
    EXPECT_GT(line_pixels, 60);
}

// The outlines are straight segments projected onto a plane: a fisheye or panorama camera is
// refused by name rather than drawn as if it were a perspective one.
TEST(Preview, CurvedProjectionsAreRefusedByTheirPointer) {
    for (const Projection projection : {Projection::Fisheye, Projection::Spherical}) {
        SceneDescription d = sphere_scene();
        d.scene.camera.projection = projection;
        d.scene.camera.hfov_degrees.reset();
        try {
            render_preview(d, PreviewOptions{});
            ADD_FAILURE() << projection_name(projection) << " was drawn";
        } catch (const InputError& e) {
            EXPECT_EQ(e.where(), "<preview test>#/camera/projection");
            EXPECT_NE(e.message().find(projection_name(projection)), std::string::npos)
                << e.message();
        }
    }
}

}  // namespace
}  // namespace rayo
