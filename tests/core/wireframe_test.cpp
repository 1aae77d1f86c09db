// Tests of the wireframe (core/wireframe.h, core/line_raster.h): segments behind the eye, cut at
// the eye's plane or the window, DDA pixels, and the drawn sphere outline against the sphere's
// ray-traced silhouette (a hit test per pixel with the window camera's rays).
#include "core/wireframe.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/line_raster.h"

namespace rayo {
namespace {

CameraDesc front_desc(int width, int height) {
    CameraDesc desc;
    desc.eye = Vec3(0, 0, 5);
    desc.look_at = Vec3(0);
    desc.up = Vec3(0, 1, 0);
    desc.hfov_degrees = 50.0f;
    desc.width = width;
    desc.height = height;
    return desc;
}

TEST(ProjectSegment, WhollyBehindTheEyeIsClippedAway) {
    const SyntheticCamera camera(Camera::create(front_desc(64, 64)));
    DVec2 a, b;
    EXPECT_EQ(project_segment(camera, DVec3(0, 0, 6), DVec3(1, 1, 9), a, b), SegmentFate::Behind);
}

TEST(ProjectSegment, CrossingTheEyesPlaneIsCutNotMirrored) {
    // From in front of the eye (x = 0.5 at depth 5) to behind it: the visible part runs from the
    // front point outwards to the right; a projection of the far end would land on the left.
    const SyntheticCamera camera(Camera::create(front_desc(64, 64)));
    DVec2 a, b;
    ASSERT_EQ(project_segment(camera, DVec3(0.5, 0, 0), DVec3(0.5, 0, 10), a, b), SegmentFate::Cut);
    const DVec2 front = camera.project(DVec3(0.5, 0, 0));
    EXPECT_EQ(a, front);
    EXPECT_NEAR(b.x, camera.window().x_max, 1e-9);
    EXPECT_NEAR(b.y, 31.5, 1e-9);
}

TEST(ProjectSegment, InsideIsWholeAndOutsideIsClippedAway) {
    const SyntheticCamera camera(Camera::create(front_desc(64, 64)));
    DVec2 a, b;
    EXPECT_EQ(project_segment(camera, DVec3(-0.5, 0, 0), DVec3(0.5, 0.2, 0), a, b),
              SegmentFate::Whole);
    EXPECT_EQ(project_segment(camera, DVec3(30, 0, 0), DVec3(40, 1, 0), a, b),
              SegmentFate::Outside);
    EXPECT_EQ(project_segment(camera, DVec3(0, 0, 0), DVec3(40, 0, 0), a, b), SegmentFate::Cut);
}

TEST(DrawLine, DdaSetsOnePixelPerStepOfTheMajorAxis) {
    Film film(8, 6);
    draw_line(film, DVec2(1, 1), DVec2(7, 4), Vec3(1, 0, 0));
    // Steps of (1, 0.5): y = 1, 1.5, 2, 2.5, 3, 3.5, 4 rounded half up.
    const int expected_y[] = {1, 2, 2, 3, 3, 4, 4};
    int lit = 0;
    for (int y = 0; y < 6; ++y) {
        for (int x = 0; x < 8; ++x) {
            const bool on = film.rgba()[(static_cast<size_t>(y) * 8 + x) * 4 + 3] == 1.0f;
            lit += on;
            if (x >= 1 && x <= 7) {
                EXPECT_EQ(on, y == expected_y[x - 1]) << x << "," << y;
            } else {
                EXPECT_FALSE(on) << x << "," << y;
            }
        }
    }
    EXPECT_EQ(lit, 7);
    EXPECT_EQ(film.rgb(7, 4), Vec3(1, 0, 0));
}

TEST(DrawLine, PointsOffTheFilmAreSkipped) {
    Film film(4, 4);
    draw_line(film, DVec2(-0.5, 3.5), DVec2(3.5, 3.5), Vec3(1));  // the window's bottom edge
    for (int x = 0; x < 4; ++x) EXPECT_EQ(film.rgb(x, 3), Vec3(1));
}

// The sphere's ray-traced silhouette: pixels whose centre ray hits the sphere with a 4-neighbour
// whose ray misses it.
std::vector<bool> hit_mask(const Camera& camera, const Sphere& sphere) {
    std::vector<bool> hit(static_cast<size_t>(camera.width()) * camera.height());
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const Ray ray = camera.generate_ray(static_cast<float>(x), static_cast<float>(y));
            ShapeHit h;
            hit[static_cast<size_t>(y) * camera.width() + x] = sphere.nearest(
                ray.origin, ray.direction, 0.0f, std::numeric_limits<float>::infinity(), h);
        }
    }
    return hit;
}

struct Pixel {
    int x, y;
};

std::vector<Pixel> silhouette(const Camera& camera, const std::vector<bool>& hit) {
    const int w = camera.width(), h = camera.height();
    const auto at = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && hit[static_cast<size_t>(y) * w + x];
    };
    std::vector<Pixel> out;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (at(x, y) && (!at(x - 1, y) || !at(x + 1, y) || !at(x, y - 1) || !at(x, y + 1))) {
                out.push_back({x, y});
            }
        }
    }
    return out;
}

// Within one pixel: the other set has a pixel in the 3×3 neighbourhood.
bool has_neighbour(const std::vector<Pixel>& set, const Pixel& p) {
    return std::any_of(set.begin(), set.end(), [&](const Pixel& q) {
        return std::abs(q.x - p.x) <= 1 && std::abs(q.y - p.y) <= 1;
    });
}

TEST(Wireframe, SphereOutlineLandsOnTheRayTracedSilhouette) {
    // Off-centre spheres under a wide and a narrow NFF camera: the silhouettes are ellipses.
    for (const bool nff : {false, true}) {
        CameraDesc desc = front_desc(160, 120);
        desc.hfov_degrees = nff ? 70.0f : 30.0f;
        desc.fov_spans_pixel_centres = nff;
        const Camera camera = Camera::create(desc);
        Scene scene;
        scene.camera = desc;
        const Sphere sphere{nff ? Vec3(2.2f, 1.1f, -1.0f) : Vec3(0.3f, -0.2f, 0.5f),
                            nff ? 0.8f : 0.5f, 0};
        scene.shapes.of<Sphere>().push_back(sphere);

        Film film(desc.width, desc.height);
        const WireframeStats stats = draw_wireframe(scene, camera, film, Vec3(1));
        EXPECT_EQ(stats.objects, 1u);
        EXPECT_EQ(stats.drawn, stats.segments);
        std::vector<Pixel> drawn;
        for (int y = 0; y < desc.height; ++y) {
            for (int x = 0; x < desc.width; ++x) {
                if (film.rgba()[(static_cast<size_t>(y) * desc.width + x) * 4 + 3] > 0.0f) {
                    drawn.push_back({x, y});
                }
            }
        }
        const std::vector<Pixel> edge = silhouette(camera, hit_mask(camera, sphere));
        ASSERT_GT(edge.size(), 50u);
        ASSERT_GT(drawn.size(), 50u);
        int far_edge = 0, far_drawn = 0;
        for (const Pixel& p : edge) far_edge += !has_neighbour(drawn, p);
        for (const Pixel& p : drawn) far_drawn += !has_neighbour(edge, p);
        EXPECT_EQ(far_edge, 0) << "silhouette pixels more than 1 px from the drawn outline";
        EXPECT_EQ(far_drawn, 0) << "outline pixels more than 1 px from the silhouette";
    }
}

TEST(Wireframe, CountsEveryObjectAndClippedSegment) {
    CameraDesc desc = front_desc(64, 64);
    Scene scene;
    scene.camera = desc;
    scene.shapes.of<Box>().push_back(Box{Vec3(-0.5f), Vec3(0.5f), 0});          // in view: 12 whole
    scene.shapes.of<Box>().push_back(Box{Vec3(40, 0, -1), Vec3(41, 1, 0), 0});  // far to the side
    scene.shapes.of<Box>().push_back(Box{Vec3(-1, -1, 7), Vec3(1, 1, 8), 0});   // behind the eye
    Film film(64, 64);
    const WireframeStats stats = draw_wireframe(scene, Camera::create(desc), film, Vec3(1));
    EXPECT_EQ(stats.objects, 3u);
    EXPECT_EQ(stats.segments, 36u);
    EXPECT_EQ(stats.drawn, 12u);
    EXPECT_EQ(stats.cut, 0u);
    EXPECT_EQ(stats.outside, 12u);
    EXPECT_EQ(stats.behind, 12u);
}

}  // namespace
}  // namespace rayo
