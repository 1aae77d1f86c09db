#pragma once
// The seed 002 window camera: EYE, LOOKAT, UP, distance, field of view and resolution define a
// window in front of the eye; one ray goes through each pixel centre, pixel (0,0) top left.
// Built for a right-handed world: camera +X is screen right, so the image is not mirrored.
// Seed 004's extensions: a thin lens (the extended pupil: depth of field) and two curved-eye
// projections, the equidistant fisheye and the equirectangular (spherical) panorama.
#include <glm/vec2.hpp>
#include <optional>
#include <string>

#include "core/ray.h"
#include "core/setting.h"

namespace rayo {

// How film positions map to directions. Perspective is seed 002's window; fisheye is equidistant
// (angle from the view axis proportional to the distance from the image centre); spherical is
// the equirectangular 360° × 180° panorama.
enum class Projection { Perspective, Fisheye, Spherical };

// The scene-file names ("perspective", "fisheye", "spherical"); nullopt for any other name.
std::optional<Projection> parse_projection(const std::string& name);
const char* projection_name(Projection projection);

// The fisheye's full angle of the image circle is in (0°, kMaxFisheyeFov].
constexpr float kMaxFisheyeFov = 360.0f;

// Largest accepted image: 65536 pixels a side (docs/limits.md, "Resolution"): film positions are
// floats, which at x = 65536 (2^16) still place samples on a 1/256-pixel lattice, and tile and
// pixel indices stay far inside int and size_t. Images above kMaxFilmPixels (core/film.h) are
// rendered only by streaming to a file (core/image/tile_stream.h).
constexpr int kMaxImageSide = 65536;

struct CameraDesc {
    Vec3 eye{0.0f, 0.0f, 5.0f};
    Vec3 look_at{0.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float distance = 1.0f;              // seed 002 `dis`
    std::optional<float> hfov_degrees;  // at least one of hfov/vfov; the other follows from
    std::optional<float> vfov_degrees;  // the aspect ratio (square pixels)
    int width = 100;
    int height = 100;
    // NFF convention: `angle` spans the centres of the first and last pixel rows/columns,
    // not the image edges (docs/nff.md).
    bool fov_spans_pixel_centres = false;

    Projection projection = Projection::Perspective;
    // Fisheye only: the full angle, degrees, of the image circle, the circle inscribed in the
    // image's shorter side; pixels outside it have no ray.
    float fisheye_fov_degrees = 180.0f;
    // Thin lens (seed 004, the extended pupil; perspective only): lens radius in world units, 0 =
    // pinhole, and the distance along the view direction of the plane in focus (default: the
    // eye–look_at distance).
    float lens_radius = 0.0f;
    std::optional<float> focus_distance;

    // The image size, declared once (core/setting.h): the scene reader's "camera": {"width",
    // "height"} and the command line's --width/--height are checked by these bounds, in the
    // same words.
    template <typename F>
    void resolution_fields(F& f) {
        f.integer({"width", "image width in pixels"}, width, 1, kMaxImageSide);
        f.integer({"height", "image height in pixels"}, height, 1, kMaxImageSide);
    }
};

class Camera {
  public:
    // Validates (throws InputError naming `where`): eye = look-at, up parallel to the view
    // direction, distance <= 0, perspective fov outside (0°, 180°), fisheye fov outside (0°,
    // 360°], lens_radius < 0 (or > 0 with a curved projection), focus_distance <= 0, non-finite
    // values, resolution <= 0 or above the limits.
    static Camera create(const CameraDesc& desc, const std::string& where = "camera");

    // The camera interface (core/render.h): the ray through film position `film` in pixel units
    // ((i, j) is the centre of pixel (i, j)) and lens position `lens` in [0, 1)²; false where
    // the camera has no ray (outside a fisheye's image circle). The perspective pinhole, the
    // common case, is inline and first; the others are out of line.
    bool generate_ray(const glm::vec2& film, const glm::vec2& lens, Ray& ray) const {
        if (!m_pinhole) return generate_other_ray(film, lens, ray);
        ray.origin = m_eye;
        ray.direction = glm::normalize(window_from_eye(film));
        return true;
    }
    // The pinhole ray through (px, py), for callers that have no lens sample.
    Ray generate_ray(float px, float py) const {
        Ray ray;
        generate_ray(glm::vec2(px, py), glm::vec2(0.5f), ray);
        return ray;
    }

    const CameraDesc& desc() const { return m_desc; }
    int width() const { return m_desc.width; }
    int height() const { return m_desc.height; }
    Vec3 right() const { return m_right; }
    Vec3 up() const { return m_up; }
    Vec3 view() const { return m_view; }
    float hfov_degrees() const { return m_hfov_degrees; }
    float vfov_degrees() const { return m_vfov_degrees; }
    Projection projection() const { return m_desc.projection; }
    float lens_radius() const { return m_desc.lens_radius; }
    float focus_distance() const { return m_focus_distance; }
    // The angle a pixel subtends at the image centre, radians (for error budgets in pixels).
    float pixel_angle() const { return m_pixel_angle; }

  private:
    bool generate_other_ray(const glm::vec2& film, const glm::vec2& lens, Ray& ray) const;
    // The point of the window at film position `film`, relative to the eye: summed there, not
    // in world space, so that an eye far from the origin (1e7 and beyond, where a float's ulp
    // exceeds the window's size) keeps every pixel's direction (docs/limits.md, "Scale").
    Vec3 window_from_eye(const glm::vec2& film) const {
        return m_origin_from_eye + film.x * m_step_right - film.y * m_step_down;
    }

    CameraDesc m_desc;
    Vec3 m_eye{0.0f};
    Vec3 m_view{0.0f}, m_right{0.0f}, m_up{0.0f};
    Vec3 m_origin_from_eye{0.0f};  // centre of pixel (0,0), seed 002 ORIGIN, minus EYE
    Vec3 m_step_right{0.0f};       // hpixel·HORZ
    Vec3 m_step_down{0.0f};        // vpixel·VERT
    float m_hfov_degrees = 0.0f, m_vfov_degrees = 0.0f;
    float m_pixel_angle = 0.0f;
    bool m_pinhole = true;  // perspective without a lens: the inline path
    float m_focus_distance = 1.0f;
    // Curved projections: the image centre in pixel units and the angle per pixel, radians.
    glm::vec2 m_centre{0.0f};
    float m_radians_per_pixel_x = 0.0f, m_radians_per_pixel_y = 0.0f;
    float m_circle_radius = 0.0f;  // fisheye image circle, pixels
};

}  // namespace rayo
