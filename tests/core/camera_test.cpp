// Tests of the seed 002 window camera (core/camera.h): pixel-centre rays, orientation in a
// right-handed world, field-of-view variants, the NFF fov convention and input validation; the
// seed 004 extensions: the thin lens, the fisheye and the spherical panorama.
#include "core/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec_near;

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// Eye on +z looking at the origin with +y up: the default right-handed set-up.
CameraDesc front_camera(int width, int height) {
    CameraDesc desc;
    desc.eye = Vec3(0.0f, 0.0f, 5.0f);
    desc.look_at = Vec3(0.0f);
    desc.up = Vec3(0.0f, 1.0f, 0.0f);
    desc.width = width;
    desc.height = height;
    return desc;
}

double angle_degrees(const Vec3& a, const Vec3& b) {
    const DVec3 da = glm::normalize(DVec3(a)), db = glm::normalize(DVec3(b));
    return std::acos(glm::clamp(glm::dot(da, db), -1.0, 1.0)) / kDegree;
}

// Where the ray through (px, py) meets the window plane, in units of the distance: the window
// coordinates of seed 002 (ORIGIN + i·hpixel·HORZ − j·vpixel·VERT relative to CENTER).
Vec3 on_window(const Camera& camera, float px, float py) {
    const Ray ray = camera.generate_ray(px, py);
    return ray.direction / glm::dot(ray.direction, camera.view());
}

TEST(Camera, CentrePixelOfOddImageLooksAlongTheViewDirection) {
    CameraDesc desc = front_camera(3, 3);
    desc.hfov_degrees = 90.0f;
    const Camera camera = Camera::create(desc);
    const Ray ray = camera.generate_ray(1.0f, 1.0f);
    // seed 002: VIEW = (LOOKAT − EYE)/|…| = (0,0,−1); the centre pixel's ray passes CENTER.
    expect_vec_near(ray.direction, Vec3(0.0f, 0.0f, -1.0f), 1e-6f);
    expect_vec_near(ray.origin, desc.eye, 0.0f);
    expect_vec_near(camera.view(), Vec3(0.0f, 0.0f, -1.0f), 1e-6f);
}

TEST(Camera, TopLeftPixelHasPositiveUpAndNegativeRightComponents) {
    CameraDesc desc = front_camera(3, 3);
    desc.hfov_degrees = 90.0f;
    const Camera camera = Camera::create(desc);
    const Ray ray = camera.generate_ray(0.0f, 0.0f);
    EXPECT_GT(glm::dot(ray.direction, camera.up()), 0.0f);
    EXPECT_LT(glm::dot(ray.direction, camera.right()), 0.0f);
    // seed 002 with dis = 1, hfov = 90°: hsize = 2·tan 45° = 2, hpixel = vpixel = 2/3, so pixel
    // (0,0) sits at CENTER − (2/3)·HORZ + (2/3)·VERT = (−2/3, 2/3, −1) from the eye; normalised
    // by √(17)/3 that is (−2, 2, −3)/√17.
    const float s = 1.0f / std::sqrt(17.0f);
    expect_vec_near(ray.direction, Vec3(-2.0f * s, 2.0f * s, -3.0f * s), 1e-6f);
    // Bottom-right is the mirror image through the view axis.
    expect_vec_near(camera.generate_ray(2.0f, 2.0f).direction, Vec3(2.0f * s, -2.0f * s, -3.0f * s),
                    1e-6f);
}

TEST(Camera, RightHandedWorldIsNotMirrored) {
    CameraDesc desc = front_camera(64, 48);
    desc.hfov_degrees = 60.0f;
    const Camera camera = Camera::create(desc);
    // Eye on +z looking at −z with +y up: screen right must be world +x (x = y × z would give
    // the seed's left-handed, mirrored frame, −x).
    expect_vec_near(camera.right(), Vec3(1.0f, 0.0f, 0.0f), 1e-6f);
    expect_vec_near(camera.up(), Vec3(0.0f, 1.0f, 0.0f), 1e-6f);
    // Pixel columns grow toward +x, rows toward −y.
    EXPECT_GT(camera.generate_ray(63.0f, 24.0f).direction.x, 0.0f);
    EXPECT_LT(camera.generate_ray(0.0f, 24.0f).direction.x, 0.0f);
    EXPECT_GT(camera.generate_ray(32.0f, 0.0f).direction.y, 0.0f);
    EXPECT_LT(camera.generate_ray(32.0f, 47.0f).direction.y, 0.0f);
}

// The pixel whose centre ray points closest to `target`.
void closest_pixel(const Camera& camera, const Vec3& target, int& best_i, int& best_j) {
    double best = -2.0;
    for (int j = 0; j < camera.height(); ++j) {
        for (int i = 0; i < camera.width(); ++i) {
            const Ray ray = camera.generate_ray(float(i), float(j));
            const double c =
                glm::dot(DVec3(ray.direction), glm::normalize(DVec3(target - ray.origin)));
            if (c > best) {
                best = c;
                best_i = i;
                best_j = j;
            }
        }
    }
}

TEST(Camera, PointsProjectIntoTheMatchingHalfOfTheImage) {
    // A general view (eye off-axis, look-at not the origin) so the test does not rely on the
    // frame being axis-aligned.
    CameraDesc desc;
    desc.eye = Vec3(3.0f, 2.0f, 7.0f);
    desc.look_at = Vec3(-1.0f, 0.5f, 0.0f);
    desc.up = Vec3(0.0f, 1.0f, 0.0f);
    desc.width = 41;
    desc.height = 31;
    desc.hfov_degrees = 50.0f;
    const Camera camera = Camera::create(desc);
    // Screen right and up of a right-handed world, from the description alone (not from the
    // camera's own frame, which a mirrored camera would get consistently wrong).
    const Vec3 view = glm::normalize(desc.look_at - desc.eye);
    const Vec3 right = glm::normalize(glm::cross(view, desc.up));
    const Vec3 up = glm::cross(right, view);
    int i = -1, j = -1;
    closest_pixel(camera, desc.look_at + 1.0f * right, i, j);
    EXPECT_GT(i, 20);  // right of the centre column (20)
    EXPECT_EQ(j, 15);  // on the centre row
    closest_pixel(camera, desc.look_at - 1.0f * right, i, j);
    EXPECT_LT(i, 20);
    EXPECT_EQ(j, 15);
    closest_pixel(camera, desc.look_at + 1.0f * up, i, j);
    EXPECT_EQ(i, 20);
    EXPECT_LT(j, 15);  // rows count downwards: above the centre is a smaller j
    closest_pixel(camera, desc.look_at, i, j);
    EXPECT_EQ(i, 20);
    EXPECT_EQ(j, 15);
    // The camera's frame is that right-handed frame: right × up = −view (it looks down −z).
    expect_vec_near(camera.right(), right, 1e-6f);
    expect_vec_near(camera.up(), up, 1e-6f);
    expect_vec_near(glm::cross(camera.right(), camera.up()), -camera.view(), 1e-6f);
}

TEST(Camera, HfovOnlyGivesSquarePixels) {
    CameraDesc desc = front_camera(200, 100);
    desc.hfov_degrees = 60.0f;
    const Camera camera = Camera::create(desc);
    const Vec3 o = on_window(camera, 10.0f, 10.0f);
    const float step_x = glm::length(on_window(camera, 11.0f, 10.0f) - o);
    const float step_y = glm::length(on_window(camera, 10.0f, 11.0f) - o);
    // hpixel = 2·tan 30°/200 (seed 002) and vpixel = hpixel.
    const float hpixel = 2.0f * std::tan(30.0f * float(kDegree)) / 200.0f;
    EXPECT_NEAR(step_x, hpixel, 1e-6f);
    EXPECT_NEAR(step_y, hpixel, 1e-6f);
    EXPECT_NEAR(camera.hfov_degrees(), 60.0f, 1e-4f);
    // vfov from the aspect ratio: 2·atan(tan 30° · 100/200) = 32.2042°.
    EXPECT_NEAR(camera.vfov_degrees(), 2.0 * std::atan(std::tan(30.0 * kDegree) / 2.0) / kDegree,
                1e-4);
    EXPECT_NEAR(camera.vfov_degrees(), 32.2042f, 1e-3f);
}

TEST(Camera, VfovOnlyGivesSquarePixels) {
    CameraDesc desc = front_camera(200, 100);
    desc.vfov_degrees = 40.0f;
    const Camera camera = Camera::create(desc);
    const Vec3 o = on_window(camera, 150.0f, 70.0f);
    const float step_x = glm::length(on_window(camera, 151.0f, 70.0f) - o);
    const float step_y = glm::length(on_window(camera, 150.0f, 71.0f) - o);
    const float vpixel = 2.0f * std::tan(20.0f * float(kDegree)) / 100.0f;
    EXPECT_NEAR(step_x, vpixel, 1e-6f);
    EXPECT_NEAR(step_y, vpixel, 1e-6f);
    EXPECT_NEAR(camera.vfov_degrees(), 40.0f, 1e-4f);
    // hfov = 2·atan(2·tan 20°) = 72.1048°.
    EXPECT_NEAR(camera.hfov_degrees(), 72.1048f, 1e-3f);
    // The image edges: the ray through the middle of the top edge makes vfov/2 with the view.
    EXPECT_NEAR(angle_degrees(camera.generate_ray(99.5f, -0.5f).direction, camera.view()), 20.0,
                1e-3);
}

TEST(Camera, BothFovsGivenAreHonouredIndependently) {
    CameraDesc desc = front_camera(4, 3);
    desc.hfov_degrees = 90.0f;
    desc.vfov_degrees = 60.0f;
    desc.distance = 2.5f;  // the field of view does not depend on dis
    const Camera camera = Camera::create(desc);
    EXPECT_NEAR(camera.hfov_degrees(), 90.0f, 1e-4f);
    EXPECT_NEAR(camera.vfov_degrees(), 60.0f, 1e-4f);
    // Edges of the image: left edge middle (px = −0.5, py = 1) is 45° off the view direction,
    // top edge middle (px = 1.5, py = −0.5) is 30° off it.
    EXPECT_NEAR(angle_degrees(camera.generate_ray(-0.5f, 1.0f).direction, camera.view()), 45.0,
                1e-3);
    EXPECT_NEAR(angle_degrees(camera.generate_ray(1.5f, -0.5f).direction, camera.view()), 30.0,
                1e-3);
    // Non-square pixels: hpixel = 2·tan 45°/4 = 0.5, vpixel = 2·tan 30°/3 = 0.3849 (per unit dis).
    const Vec3 o = on_window(camera, 1.0f, 1.0f);
    EXPECT_NEAR(glm::length(on_window(camera, 2.0f, 1.0f) - o), 0.5f, 1e-5f);
    EXPECT_NEAR(glm::length(on_window(camera, 1.0f, 2.0f) - o),
                2.0 * std::tan(30.0 * kDegree) / 3.0, 1e-5);
}

TEST(Camera, NffFovSpansPixelCentres) {
    // NFF `angle` (docs/nff.md): the angle between the rays through the centres
    // of the first and last rows (and columns) equals the fov.
    CameraDesc desc = front_camera(5, 5);
    desc.vfov_degrees = 40.0f;
    desc.fov_spans_pixel_centres = true;
    const Camera camera = Camera::create(desc);
    EXPECT_NEAR(angle_degrees(camera.generate_ray(2.0f, 0.0f).direction,
                              camera.generate_ray(2.0f, 4.0f).direction),
                40.0, 1e-3);
    EXPECT_NEAR(angle_degrees(camera.generate_ray(0.0f, 2.0f).direction,
                              camera.generate_ray(4.0f, 2.0f).direction),
                40.0, 1e-3);
    // Without the flag the fov spans the image edges, so the centres span less:
    // 2·atan(tan 20° · 4/5) = 32.4686°.
    desc.fov_spans_pixel_centres = false;
    const Camera edges = Camera::create(desc);
    const double centres = angle_degrees(edges.generate_ray(2.0f, 0.0f).direction,
                                         edges.generate_ray(2.0f, 4.0f).direction);
    EXPECT_NEAR(centres, 2.0 * std::atan(std::tan(20.0 * kDegree) * 0.8) / kDegree, 1e-3);
    EXPECT_NEAR(centres, 32.4686, 1e-3);
}

TEST(Camera, NffFovSpansPixelCentresWithHfov) {
    CameraDesc desc = front_camera(9, 3);
    desc.hfov_degrees = 70.0f;
    desc.fov_spans_pixel_centres = true;
    const Camera camera = Camera::create(desc);
    EXPECT_NEAR(angle_degrees(camera.generate_ray(0.0f, 1.0f).direction,
                              camera.generate_ray(8.0f, 1.0f).direction),
                70.0, 1e-3);
}

// Expects Camera::create to refuse `desc` with an InputError that names `where`.
void expect_refused(const CameraDesc& desc, const std::string& case_name) {
    const std::string where = "scene.nff:7 [" + case_name + "]";
    try {
        Camera::create(desc, where);
        ADD_FAILURE() << case_name << ": accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), where) << case_name;
        EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << case_name;
        EXPECT_FALSE(e.message().empty()) << case_name;
    } catch (const std::exception& e) {
        ADD_FAILURE() << case_name << ": threw something other than InputError: " << e.what();
    }
}

CameraDesc valid_desc() {
    CameraDesc desc = front_camera(16, 9);
    desc.hfov_degrees = 60.0f;
    return desc;
}

TEST(Camera, ValidDescriptionIsAccepted) {
    // The base description of the refusal tests is itself valid, so each refusal below is caused
    // by the one field it changes.
    EXPECT_NO_THROW(Camera::create(valid_desc(), "base"));
    CameraDesc at_limits = valid_desc();
    at_limits.width = kMaxImageSide;
    at_limits.height = kMaxImageSide;  // 2^32 pixels: width × height overflows a 32-bit int
    EXPECT_NO_THROW(Camera::create(at_limits, "limits"));
}

TEST(Camera, RefusesDegenerateFrames) {
    CameraDesc d = valid_desc();
    d.look_at = d.eye;
    expect_refused(d, "eye = look_at");

    d = valid_desc();
    d.up = Vec3(0.0f, 0.0f, -1.0f);  // along the view direction
    expect_refused(d, "up parallel to view");
    d.up = Vec3(0.0f, 0.0f, 3.0f);  // opposite, longer
    expect_refused(d, "up antiparallel to view");

    d = valid_desc();
    d.up = Vec3(0.0f);
    expect_refused(d, "up zero");
}

TEST(Camera, RefusesNonPositiveDistance) {
    CameraDesc d = valid_desc();
    d.distance = 0.0f;
    expect_refused(d, "distance 0");
    d.distance = -1.0f;
    expect_refused(d, "distance -1");
    d.distance = std::numeric_limits<float>::quiet_NaN();
    expect_refused(d, "distance NaN");
}

TEST(Camera, RefusesFovOutsideTheOpenInterval) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (float fov : {0.0f, 180.0f, -30.0f, 200.0f, nan, inf}) {
        CameraDesc d = valid_desc();
        d.hfov_degrees = fov;
        expect_refused(d, "hfov " + std::to_string(fov));
        d = valid_desc();
        d.hfov_degrees.reset();
        d.vfov_degrees = fov;
        expect_refused(d, "vfov " + std::to_string(fov));
        d = valid_desc();
        d.vfov_degrees = fov;  // a bad vfov next to a good hfov
        expect_refused(d, "vfov with hfov " + std::to_string(fov));
    }
    CameraDesc d = valid_desc();
    d.hfov_degrees.reset();
    expect_refused(d, "no fov");
}

TEST(Camera, RefusesBadResolution) {
    for (int bad : {0, -1, -100, kMaxImageSide + 1}) {
        CameraDesc d = valid_desc();
        d.width = bad;
        expect_refused(d, "width " + std::to_string(bad));
        d = valid_desc();
        d.height = bad;
        expect_refused(d, "height " + std::to_string(bad));
    }
}

TEST(Camera, RefusesNonFiniteVectors) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    CameraDesc d = valid_desc();
    d.eye.x = nan;
    expect_refused(d, "eye NaN");
    d = valid_desc();
    d.eye.z = inf;
    expect_refused(d, "eye inf");
    d = valid_desc();
    d.eye.y = -inf;
    expect_refused(d, "eye -inf");
    d = valid_desc();
    d.look_at.y = nan;
    expect_refused(d, "look_at NaN");
    d = valid_desc();
    d.up.x = inf;
    expect_refused(d, "up inf");
}

// ---- Thin lens (seed 004: the extended pupil) ------------------------------------------------

// Where a ray meets the plane at depth `depth` along the camera's view direction.
Vec3 at_depth(const Camera& camera, const Ray& ray, float depth) {
    const float t = (depth - glm::dot(ray.origin - camera.desc().eye, camera.view())) /
                    glm::dot(ray.direction, camera.view());
    return ray.origin + t * ray.direction;
}

TEST(CameraThinLens, RaysThroughAFilmPointMeetOnTheFocalPlane) {
    CameraDesc desc = valid_desc();
    desc.lens_radius = 0.5f;
    desc.focus_distance = 7.0f;
    const Camera lens = Camera::create(desc);
    desc.lens_radius = 0.0f;
    const Camera pinhole = Camera::create(desc);
    for (const glm::vec2 film : {glm::vec2(0.0f, 0.0f), glm::vec2(7.3f, 4.1f), glm::vec2(15, 8)}) {
        const Vec3 sharp = at_depth(pinhole, pinhole.generate_ray(film.x, film.y), 7.0f);
        float widest = 0.0f;
        for (const glm::vec2 u : {glm::vec2(0.1f, 0.2f), glm::vec2(0.9f, 0.5f),
                                  glm::vec2(0.5f, 0.99f), glm::vec2(0.0f, 0.0f)}) {
            Ray ray;
            ASSERT_TRUE(lens.generate_ray(film, u, ray));
            // The origin lies on the lens disk: in the plane through the eye across the view.
            const Vec3 offset = ray.origin - desc.eye;
            EXPECT_NEAR(glm::dot(offset, lens.view()), 0.0f, 1e-6f);
            EXPECT_LE(glm::length(offset), 0.5f + 1e-6f);
            widest = std::max(widest, glm::length(offset));
            expect_vec_near(at_depth(lens, ray, 7.0f), sharp, 2e-5f);
            EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-6f);
        }
        EXPECT_GT(widest, 0.4f);  // the lens samples really spread over the aperture
    }
}

TEST(CameraThinLens, FocusDefaultsToTheLookAtDistanceAndBlursOffThePlane) {
    CameraDesc desc = valid_desc();  // eye (0, 0, 5), look_at the origin
    desc.lens_radius = 0.2f;
    const Camera camera = Camera::create(desc);
    EXPECT_FLOAT_EQ(camera.focus_distance(), 5.0f);
    Ray a, b;
    ASSERT_TRUE(camera.generate_ray(glm::vec2(8.0f, 4.0f), glm::vec2(0.0f, 0.5f), a));
    ASSERT_TRUE(camera.generate_ray(glm::vec2(8.0f, 4.0f), glm::vec2(1.0f, 0.5f), b));
    // Opposite ends of the lens: meet at depth 5, apart at depth 10 by the circle of confusion,
    // 2·radius·|z − F|/F = 0.4 (similar triangles).
    expect_vec_near(at_depth(camera, a, 5.0f), at_depth(camera, b, 5.0f), 1e-5f);
    EXPECT_NEAR(glm::length(at_depth(camera, a, 10.0f) - at_depth(camera, b, 10.0f)), 0.4f, 1e-5f);
}

TEST(CameraThinLens, RefusesNegativeRadiusAndNonPositiveFocus) {
    CameraDesc d = valid_desc();
    d.lens_radius = -0.1f;
    expect_refused(d, "lens_radius -0.1");
    d.lens_radius = std::numeric_limits<float>::quiet_NaN();
    expect_refused(d, "lens_radius NaN");
    for (float focus : {0.0f, -2.0f, std::numeric_limits<float>::infinity()}) {
        d = valid_desc();
        d.focus_distance = focus;
        expect_refused(d, "focus_distance " + std::to_string(focus));
    }
    d = valid_desc();
    d.hfov_degrees.reset();
    d.projection = Projection::Fisheye;
    d.lens_radius = 0.1f;
    expect_refused(d, "lens on a fisheye");
}

// ---- Fisheye and spherical projections (seed 004: the curved eye) -----------------------------

// The unit direction at `degrees` from the view direction (0, 0, −1), turned toward `side`.
Vec3 tilted(double degrees, const Vec3& side) {
    const double a = degrees * kDegree;
    return glm::normalize(Vec3(float(std::cos(a)) * Vec3(0, 0, -1) + float(std::sin(a)) * side));
}

Camera curved_camera(Projection projection, int width, int height, float fov = 180.0f) {
    CameraDesc desc = front_camera(width, height);
    desc.projection = projection;
    desc.fisheye_fov_degrees = fov;
    return Camera::create(desc);
}

Vec3 direction_at(const Camera& camera, float x, float y) {
    Ray ray;
    EXPECT_TRUE(camera.generate_ray(glm::vec2(x, y), glm::vec2(0.5f), ray)) << x << ", " << y;
    return ray.direction;
}

TEST(CameraFisheye, AngleFromTheAxisGrowsLinearlyToHalfTheFovOnTheRim) {
    // 101 × 81: the image circle is inscribed in the height, radius 40.5 pixels about the centre
    // pixel (50, 40); its rim is fov/2 = 90° from the view direction.
    const Camera camera = curved_camera(Projection::Fisheye, 101, 81);
    const Vec3 right(1, 0, 0), up(0, 1, 0);
    expect_vec_near(direction_at(camera, 50.0f, 40.0f), Vec3(0, 0, -1), 1e-6f);
    for (double degrees : {10.0, 45.0, 90.0}) {
        const float r = float(40.5 * degrees / 90.0);
        expect_vec_near(direction_at(camera, 50.0f + r, 40.0f), tilted(degrees, right), 1e-5f);
        expect_vec_near(direction_at(camera, 50.0f - r, 40.0f), tilted(degrees, -right), 1e-5f);
        expect_vec_near(direction_at(camera, 50.0f, 40.0f - r), tilted(degrees, up), 1e-5f);
        // Along the diagonal too: equidistant in every direction.
        const float d = r / std::sqrt(2.0f);
        expect_vec_near(direction_at(camera, 50.0f + d, 40.0f + d),
                        tilted(degrees, glm::normalize(right - up)), 1e-5f);
    }
    EXPECT_NEAR(camera.pixel_angle(), kPi / 81.0f, 1e-7f);
}

TEST(CameraFisheye, NoRayOutsideTheImageCircle) {
    const Camera camera = curved_camera(Projection::Fisheye, 101, 81);
    Ray ray;
    EXPECT_FALSE(camera.generate_ray(glm::vec2(0.0f, 0.0f), glm::vec2(0.5f), ray));  // corner
    EXPECT_FALSE(camera.generate_ray(glm::vec2(50.0f + 40.6f, 40.0f), glm::vec2(0.5f), ray));
    EXPECT_TRUE(camera.generate_ray(glm::vec2(50.0f + 40.4f, 40.0f), glm::vec2(0.5f), ray));
    EXPECT_TRUE(camera.generate_ray(glm::vec2(50.0f, 40.0f - 40.5f), glm::vec2(0.5f), ray));
}

TEST(CameraFisheye, FullSphereLooksBackwardOnTheRim) {
    // fov 360: half-way out is 90° (sideways), the rim straight behind the camera.
    const Camera camera = curved_camera(Projection::Fisheye, 64, 64, 360.0f);
    expect_vec_near(direction_at(camera, 31.5f + 16.0f, 31.5f), Vec3(1, 0, 0), 1e-5f);
    expect_vec_near(direction_at(camera, 31.5f, 31.5f + 16.0f), Vec3(0, -1, 0), 1e-5f);
    expect_vec_near(direction_at(camera, 31.5f - 32.0f, 31.5f), Vec3(0, 0, 1), 1e-5f);
    // A narrow fisheye: 60° across the circle, so 30° on its rim.
    const Camera narrow = curved_camera(Projection::Fisheye, 64, 64, 60.0f);
    expect_vec_near(direction_at(narrow, 31.5f + 32.0f, 31.5f), tilted(30.0, Vec3(1, 0, 0)), 1e-5f);
}

TEST(CameraFisheye, RefusesFovOutsideZeroTo360AndPerspectiveAngles) {
    for (float fov : {0.0f, -10.0f, 360.5f, std::numeric_limits<float>::quiet_NaN()}) {
        CameraDesc d = front_camera(16, 16);
        d.projection = Projection::Fisheye;
        d.fisheye_fov_degrees = fov;
        expect_refused(d, "fisheye fov " + std::to_string(fov));
    }
    CameraDesc d = front_camera(16, 16);
    d.projection = Projection::Fisheye;
    d.fisheye_fov_degrees = 360.0f;
    EXPECT_NO_THROW(Camera::create(d));
    d.vfov_degrees = 40.0f;
    expect_refused(d, "vfov on a fisheye");
    d.vfov_degrees.reset();
    d.projection = Projection::Spherical;
    d.hfov_degrees = 40.0f;
    expect_refused(d, "hfov on a panorama");
}

TEST(CameraSpherical, LongitudeAcrossLatitudeDown) {
    // 360° over 200 pixels, 180° over 100: the image centre (99.5, 49.5) looks along the view.
    const Camera camera = curved_camera(Projection::Spherical, 200, 100);
    expect_vec_near(direction_at(camera, 99.5f, 49.5f), Vec3(0, 0, -1), 1e-6f);
    expect_vec_near(direction_at(camera, 99.5f + 50.0f, 49.5f), Vec3(1, 0, 0), 1e-5f);   // +90°
    expect_vec_near(direction_at(camera, 99.5f - 50.0f, 49.5f), Vec3(-1, 0, 0), 1e-5f);  // −90°
    expect_vec_near(direction_at(camera, -0.5f, 49.5f), Vec3(0, 0, 1), 1e-5f);  // left edge: behind
    expect_vec_near(direction_at(camera, 199.5f, 49.5f), Vec3(0, 0, 1), 1e-5f);  // right edge too
    expect_vec_near(direction_at(camera, 99.5f, -0.5f), Vec3(0, 1, 0), 1e-5f);   // top: zenith
    expect_vec_near(direction_at(camera, 99.5f, 99.5f), Vec3(0, -1, 0), 1e-5f);  // bottom: nadir
    // Latitude 45° up at longitude 45° right.
    expect_vec_near(direction_at(camera, 99.5f + 25.0f, 49.5f - 25.0f),
                    glm::normalize(Vec3(0.5f, std::sqrt(0.5f), -0.5f)), 1e-5f);
    EXPECT_EQ(camera.hfov_degrees(), 360.0f);
    EXPECT_EQ(camera.vfov_degrees(), 180.0f);
}

TEST(CameraPerspective, PixelAngleIsTheCentrePixelsAngle) {
    CameraDesc desc = front_camera(100, 50);
    desc.vfov_degrees = 90.0f;
    const Camera camera = Camera::create(desc);
    // The window is 2·tan(45°) = 2 units high at unit distance: 0.04 per pixel.
    EXPECT_NEAR(camera.pixel_angle(), 0.04f, 1e-6f);
}

}  // namespace
}  // namespace rayo
