#include "core/camera.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace rayo {
namespace {

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

float radians(float degrees) {
    return degrees * kPi / 180.0f;
}
float degrees(float radians) {
    return radians * 180.0f / kPi;
}

void check_fov(const std::optional<float>& fov, const std::string& where, const char* name) {
    if (fov && !(*fov > 0.0f && *fov < 180.0f)) {
        throw InputError(
            where, std::string(name) + " must be in (0, 180) degrees, got " + std::to_string(*fov));
    }
}

}  // namespace

Camera Camera::create(const CameraDesc& desc, const std::string& where) {
    if (!finite(desc.eye) || !finite(desc.look_at) || !finite(desc.up) ||
        !std::isfinite(desc.distance)) {
        throw InputError(where, "camera vectors and distance must be finite numbers");
    }
    if (desc.width <= 0 || desc.height <= 0) {
        throw InputError(where, "resolution must be positive, got " + std::to_string(desc.width) +
                                    "x" + std::to_string(desc.height));
    }
    if (desc.width > kMaxImageSide || desc.height > kMaxImageSide ||
        static_cast<long long>(desc.width) * desc.height > kMaxImagePixels) {
        throw InputError(where, "resolution " + std::to_string(desc.width) + "x" +
                                    std::to_string(desc.height) + " exceeds the limit of " +
                                    std::to_string(kMaxImageSide) + " pixels a side and " +
                                    std::to_string(kMaxImagePixels) + " pixels in all");
    }
    if (!(desc.distance > 0.0f)) {
        throw InputError(where, "distance must be > 0, got " + std::to_string(desc.distance));
    }
    const Vec3 to_target = desc.look_at - desc.eye;
    if (!(glm::length(to_target) > 0.0f)) {
        throw InputError(where, "eye and look_at must differ");
    }
    check_fov(desc.hfov_degrees, where, "hfov");
    check_fov(desc.vfov_degrees, where, "vfov");
    if (!desc.hfov_degrees && !desc.vfov_degrees) {
        throw InputError(where, "one of hfov or vfov is required");
    }

    Camera camera;
    camera.m_desc = desc;
    camera.m_eye = desc.eye;
    // seed 002: VIEW = (LOOKAT − EYE)/|…|. HORZ is VIEW × UP rather than the seed's UP × VIEW:
    // the seed's frame is left-handed, and in rayo's right-handed world that order would mirror
    // the image (seed 002).
    camera.m_view = glm::normalize(to_target);
    const Vec3 right = glm::cross(camera.m_view, desc.up);
    const float up_length = glm::length(desc.up);
    if (!(up_length > 0.0f) || glm::length(right) <= 1e-6f * up_length) {
        throw InputError(where, "up must not be zero or parallel to the view direction");
    }
    camera.m_right = glm::normalize(right);
    camera.m_up = glm::normalize(glm::cross(camera.m_right, camera.m_view));

    // Window size from the field of view (seed 002: size = 2·dis·tan(fov/2)). With
    // fov_spans_pixel_centres the fov spans (n−1) pixels instead of n.
    const float w = static_cast<float>(desc.width), h = static_cast<float>(desc.height);
    const float span_w = desc.fov_spans_pixel_centres ? std::max(w - 1.0f, 1.0f) : w;
    const float span_h = desc.fov_spans_pixel_centres ? std::max(h - 1.0f, 1.0f) : h;
    float hpixel, vpixel;
    if (desc.hfov_degrees && desc.vfov_degrees) {
        hpixel = 2.0f * desc.distance * std::tan(radians(*desc.hfov_degrees) / 2.0f) / span_w;
        vpixel = 2.0f * desc.distance * std::tan(radians(*desc.vfov_degrees) / 2.0f) / span_h;
    } else if (desc.hfov_degrees) {
        hpixel = 2.0f * desc.distance * std::tan(radians(*desc.hfov_degrees) / 2.0f) / span_w;
        vpixel = hpixel;
    } else {
        vpixel = 2.0f * desc.distance * std::tan(radians(*desc.vfov_degrees) / 2.0f) / span_h;
        hpixel = vpixel;
    }
    camera.m_hfov_degrees = 2.0f * degrees(std::atan(hpixel * w / (2.0f * desc.distance)));
    camera.m_vfov_degrees = 2.0f * degrees(std::atan(vpixel * h / (2.0f * desc.distance)));

    // seed 002: CENTER = EYE + dis·VIEW;
    // ORIGIN = CENTER − ((width−1)/2)·hpixel·HORZ + ((height−1)/2)·vpixel·VERT.
    const Vec3 center = desc.eye + desc.distance * camera.m_view;
    camera.m_step_right = hpixel * camera.m_right;
    camera.m_step_down = vpixel * camera.m_up;
    camera.m_origin = center - ((w - 1.0f) / 2.0f) * camera.m_step_right +
                      ((h - 1.0f) / 2.0f) * camera.m_step_down;
    return camera;
}

}  // namespace rayo
