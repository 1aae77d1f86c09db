#pragma once
// The seed 002 window camera: EYE, LOOKAT, UP, distance, field of view and resolution define a
// window in front of the eye; one ray goes through each pixel centre, pixel (0,0) top left.
// Built for a right-handed world: camera +X is screen right, so the image is not mirrored.
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
    // not the image edges (DESIGN.md, NFF conventions).
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

    // Ray through image position (px, py) in pixel units: (i, j) is the centre of pixel (i, j).
    Ray generate_ray(float px, float py) const {
        const Vec3 on_window = m_origin + px * m_step_right - py * m_step_down;
        Ray ray;
        ray.origin = m_eye;
        ray.direction = glm::normalize(on_window - m_eye);
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
