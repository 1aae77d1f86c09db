// Tests of the seed 003 synthetic camera (core/synthetic_camera.h): eqs. 1.3–1.5 (the frame),
// eqs. 1.9–1.10 (the projection), and agreement with the ray-tracing window camera
// (core/camera.h): a point projects to the film position whose ray passes through it, for every
// field-of-view convention.
#include "core/synthetic_camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace rayo {
namespace {

TEST(ProjectToPlane, SeedEquations19And110) {
    // o = (0, 0, −2), q = (1, 2, 2): u = −o_z/(q_z − o_z) = 1/2, x = (0·2 − 1·(−2))/4 = 0.5,
    // y = (0·2 − 2·(−2))/4 = 1.
    const DVec2 p = project_to_plane(DVec3(1, 2, 2), DVec3(0, 0, -2));
    EXPECT_DOUBLE_EQ(p.x, 0.5);
    EXPECT_DOUBLE_EQ(p.y, 1.0);
    // An observer off the axis: o = (1, 1, −1), q = (3, 2, 1): u = 1/2, o + u(q − o) = (2, 1.5, 0).
    const DVec2 r = project_to_plane(DVec3(3, 2, 1), DVec3(1, 1, -1));
    EXPECT_DOUBLE_EQ(r.x, 2.0);
    EXPECT_DOUBLE_EQ(r.y, 1.5);
}

CameraDesc front_desc() {
    CameraDesc desc;
    desc.eye = Vec3(0, 0, 5);
    desc.look_at = Vec3(0);
    desc.up = Vec3(0, 1, 0);
    desc.hfov_degrees = 60.0f;
    desc.width = 64;
    desc.height = 48;
    return desc;
}

TEST(SyntheticCamera, FrameOfEquations13To15) {
    const SyntheticCamera camera(Camera::create(front_desc()));
    // z = (c − p)/|c − p| = (0, 0, −1); y = s = (0, 1, 0); x = z × y = (1, 0, 0): screen right.
    EXPECT_EQ(camera.z(), DVec3(0, 0, -1));
    EXPECT_EQ(camera.y(), DVec3(0, 1, 0));
    EXPECT_EQ(camera.x(), DVec3(1, 0, 0));
}

TEST(SyntheticCamera, SkyIsProjectedOffTheViewDirection) {
    CameraDesc desc = front_desc();
    desc.eye = Vec3(0, 0, 0);
    desc.look_at = Vec3(0, 0, -4);
    desc.up = Vec3(0, 3, 3);  // r = s − (s·z)z = (0, 3, 0)
    const SyntheticCamera camera(Camera::create(desc));
    EXPECT_NEAR(camera.y().y, 1.0, 1e-12);
    EXPECT_NEAR(camera.y().z, 0.0, 1e-12);
}

TEST(SyntheticCamera, CentreProjectsToTheImageCentreAndUpIsUp) {
    const SyntheticCamera camera(Camera::create(front_desc()));
    const DVec2 centre = camera.project(DVec3(0, 0, -3));
    EXPECT_NEAR(centre.x, 31.5, 1e-12);  // (64 − 1)/2
    EXPECT_NEAR(centre.y, 23.5, 1e-12);  // (48 − 1)/2
    const DVec2 up_right = camera.project(DVec3(1, 1, 0));
    EXPECT_GT(up_right.x, 31.5);
    EXPECT_LT(up_right.y, 23.5);  // film y grows downward
}

TEST(SyntheticCamera, WindowIsTheImageEdges) {
    const SyntheticCamera camera(Camera::create(front_desc()));
    EXPECT_EQ(camera.window().x_min, -0.5);
    EXPECT_EQ(camera.window().y_min, -0.5);
    EXPECT_EQ(camera.window().x_max, 63.5);
    EXPECT_EQ(camera.window().y_max, 47.5);
}

TEST(SyntheticCamera, PixelAngleIsTheFinerSideOfAPixel) {
    CameraDesc desc = front_desc();  // 64×48, hfov 60°: 2·tan 30°/64 across
    EXPECT_NEAR(SyntheticCamera(Camera::create(desc)).pixel_angle(),
                2.0 * std::tan(3.14159265358979323846 / 6.0) / 64.0, 1e-7);
    desc.vfov_degrees = 20.0f;  // both given: 2·tan 10°/48 down, the smaller
    EXPECT_NEAR(SyntheticCamera(Camera::create(desc)).pixel_angle(),
                2.0 * std::tan(3.14159265358979323846 / 18.0) / 48.0, 1e-7);
}

// Cameras of every kind the window camera builds: fov across or down, both, the NFF convention,
// odd and even sizes, a tilted up vector, an eye off the axes and a long distance.
std::vector<CameraDesc> camera_variants() {
    std::vector<CameraDesc> out;
    CameraDesc a = front_desc();
    out.push_back(a);
    a.fov_spans_pixel_centres = true;
    out.push_back(a);
    CameraDesc b = front_desc();
    b.hfov_degrees.reset();
    b.vfov_degrees = 35.0f;
    b.width = 33;
    b.height = 91;
    b.eye = Vec3(3.0f, -2.0f, 7.0f);
    b.look_at = Vec3(0.5f, 0.25f, -1.0f);
    b.up = Vec3(0.3f, 1.0f, 0.2f);
    out.push_back(b);
    b.fov_spans_pixel_centres = true;
    b.distance = 40.0f;
    out.push_back(b);
    CameraDesc c = front_desc();
    c.vfov_degrees = 20.0f;  // both: non-square pixels
    c.width = 1920;
    c.height = 1080;
    c.fov_spans_pixel_centres = true;
    c.eye = Vec3(-4.0f, 10.0f, 2.0f);
    c.up = Vec3(0.0f, 0.0f, 1.0f);
    out.push_back(c);
    return out;
}

TEST(SyntheticCamera, PointOnAPixelRayProjectsToThatPixel) {
    for (const CameraDesc& desc : camera_variants()) {
        const Camera camera = Camera::create(desc);
        const SyntheticCamera synthetic(camera);
        for (const float fx : {0.0f, 0.3f, 0.5f, 0.71f, 1.0f}) {
            for (const float fy : {0.0f, 0.45f, 1.0f}) {
                // Off the pixels' borders (x.5), so that the pixel is unambiguous.
                const float px = std::floor(fx * (desc.width - 1)) + 0.2f;
                const float py = std::floor(fy * (desc.height - 1)) + 0.3f;
                const Ray ray = camera.generate_ray(px, py);
                for (const double t : {0.5, 3.0, 50.0}) {
                    const DVec3 point = DVec3(ray.origin) + t * DVec3(ray.direction);
                    const DVec2 projected = synthetic.project(point);
                    SCOPED_TRACE(std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                                 " at " + std::to_string(px) + ", " + std::to_string(py));
                    // Float rays: a few 1e-7 of the image's angular size.
                    EXPECT_NEAR(projected.x, px, 2e-3 + 2e-6 * desc.width);
                    EXPECT_NEAR(projected.y, py, 2e-3 + 2e-6 * desc.height);
                    // The pixel the ray belongs to.
                    EXPECT_EQ(std::lround(projected.x), std::lround(px));
                    EXPECT_EQ(std::lround(projected.y), std::lround(py));
                }
            }
        }
    }
}

TEST(SyntheticCamera, RayThroughTheProjectedPositionPassesThroughThePoint) {
    for (const CameraDesc& desc : camera_variants()) {
        const Camera camera = Camera::create(desc);
        const SyntheticCamera synthetic(camera);
        const DVec3 eye(desc.eye), view = synthetic.z();
        for (int k = 0; k < 40; ++k) {
            // Points spread over the view (a fixed sequence, not random state).
            const double s = std::sin(1.7 * k), c = std::cos(2.3 * k);
            const DVec3 point = eye + (2.0 + k) * view + (0.3 + 0.02 * k) * s * synthetic.x() +
                                (0.25 + 0.01 * k) * c * synthetic.y();
            const DVec2 film = synthetic.project(point);
            const Ray ray =
                camera.generate_ray(static_cast<float>(film.x), static_cast<float>(film.y));
            const DVec3 to_point = glm::normalize(point - eye);
            const double angle = glm::length(glm::cross(DVec3(ray.direction), to_point));
            EXPECT_LT(angle, 2e-6) << "point " << k;
            EXPECT_GT(glm::dot(DVec3(ray.direction), to_point), 0.0);
        }
    }
}

}  // namespace
}  // namespace rayo
