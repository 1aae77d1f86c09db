#pragma once
// The seed 002 window camera: EYE, LOOKAT, UP, distance, field of view and resolution define a
// window in front of the eye; one ray goes through each pixel centre, pixel (0,0) top left.
// Built for a right-handed world: camera +X is screen right, so the image is not mirrored.
#include <glm/vec2.hpp>
#include <optional>
#include <string>

#include "core/ray.h"

namespace rayo {

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
};

// Largest accepted image: 32768 pixels a side and 2^28 pixels in all (a 4 GiB float RGBA film).
constexpr int kMaxImageSide = 32768;
constexpr long long kMaxImagePixels = 1LL << 28;

class Camera {
  public:
    // Validates (throws InputError naming `where`): eye = look-at, up parallel to the view
    // direction, distance <= 0, fov outside (0°, 180°), non-finite values, resolution <= 0 or
    // above the limits.
    static Camera create(const CameraDesc& desc, const std::string& where = "camera");

    // The camera interface (core/render.h): the ray through film position `film` in pixel units
    // ((i, j) is the centre of pixel (i, j)) and lens position `lens` in [0, 1)²; false where
    // the camera has no ray. The window camera is a pinhole: it ignores the lens and always
    // has a ray.
    bool generate_ray(const glm::vec2& film, const glm::vec2& /*lens*/, Ray& ray) const {
        const Vec3 on_window = m_origin + film.x * m_step_right - film.y * m_step_down;
        ray.origin = m_eye;
        ray.direction = glm::normalize(on_window - m_eye);
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

  private:
    CameraDesc m_desc;
    Vec3 m_eye{0.0f};
    Vec3 m_view{0.0f}, m_right{0.0f}, m_up{0.0f};
    Vec3 m_origin{0.0f};      // centre of pixel (0,0), seed 002 ORIGIN
    Vec3 m_step_right{0.0f};  // hpixel·HORZ
    Vec3 m_step_down{0.0f};   // vpixel·VERT
    float m_hfov_degrees = 0.0f, m_vfov_degrees = 0.0f;
};

}  // namespace rayo
