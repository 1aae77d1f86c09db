#include "core/camera.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/sampling.h"

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

constexpr const char* kProjectionNames[] = {"perspective", "fisheye", "spherical"};

}  // namespace

std::optional<Projection> parse_projection(const std::string& name) {
    for (int i = 0; i < 3; ++i) {
        if (name == kProjectionNames[i]) return static_cast<Projection>(i);
    }
    return std::nullopt;
}

const char* projection_name(Projection projection) {
    return kProjectionNames[static_cast<int>(projection)];
}

Camera Camera::create(const CameraDesc& desc, const std::string& where) {
    if (!finite(desc.eye) || !finite(desc.look_at) || !finite(desc.up) ||
        !std::isfinite(desc.distance)) {
        throw InputError(where, "camera vectors and distance must be finite numbers");
    }
    if (desc.width <= 0 || desc.height <= 0) {
        throw InputError(where, "resolution must be positive, got " + std::to_string(desc.width) +
                                    "x" + std::to_string(desc.height));
    }
    if (desc.width > kMaxImageSide || desc.height > kMaxImageSide) {
        throw InputError(where, "resolution " + std::to_string(desc.width) + "x" +
                                    std::to_string(desc.height) + " exceeds the limit of " +
                                    std::to_string(kMaxImageSide) + " pixels a side");
    }
    if (!(desc.distance > 0.0f)) {
        throw InputError(where, "distance must be > 0, got " + std::to_string(desc.distance));
    }
    const Vec3 to_target = desc.look_at - desc.eye;
    if (!(glm::length(to_target) > 0.0f)) {
        throw InputError(where, "eye and look_at must differ");
    }
    const bool perspective = desc.projection == Projection::Perspective;
    if (!(std::isfinite(desc.lens_radius) && desc.lens_radius >= 0.0f)) {
        throw InputError(where,
                         "lens_radius must be >= 0, got " + std::to_string(desc.lens_radius));
    }
    if (desc.lens_radius > 0.0f && !perspective) {
        throw InputError(where, "lens_radius applies to the perspective projection only");
    }
    if (desc.focus_distance &&
        !(std::isfinite(*desc.focus_distance) && *desc.focus_distance > 0.0f)) {
        throw InputError(where,
                         "focus_distance must be > 0, got " + std::to_string(*desc.focus_distance));
    }
    if (perspective) {
        check_fov(desc.hfov_degrees, where, "hfov");
        check_fov(desc.vfov_degrees, where, "vfov");
        if (!desc.hfov_degrees && !desc.vfov_degrees) {
            throw InputError(where, "one of hfov or vfov is required");
        }
    } else if (desc.hfov_degrees || desc.vfov_degrees) {
        throw InputError(where,
                         std::string("hfov and vfov apply to the perspective projection, not ") +
                             projection_name(desc.projection));
    }
    if (desc.projection == Projection::Fisheye &&
        !(desc.fisheye_fov_degrees > 0.0f && desc.fisheye_fov_degrees <= kMaxFisheyeFov)) {
        throw InputError(where, "fisheye fov must be in (0, 360] degrees, got " +
                                    std::to_string(desc.fisheye_fov_degrees));
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
    camera.m_focus_distance = desc.focus_distance.value_or(glm::length(to_target));
    camera.m_pinhole = perspective && desc.lens_radius == 0.0f;

    const float w = static_cast<float>(desc.width), h = static_cast<float>(desc.height);
    // Curved projections measure angles from the image centre, in pixel units.
    camera.m_centre = glm::vec2((w - 1.0f) / 2.0f, (h - 1.0f) / 2.0f);
    if (desc.projection == Projection::Fisheye) {
        // The image circle is inscribed in the shorter side: its rim is fov/2 from the axis.
        const float shorter = std::min(w, h);
        camera.m_circle_radius = shorter / 2.0f;
        camera.m_radians_per_pixel_x = radians(desc.fisheye_fov_degrees) / shorter;
        camera.m_radians_per_pixel_y = camera.m_radians_per_pixel_x;
        camera.m_hfov_degrees = desc.fisheye_fov_degrees * w / shorter;
        camera.m_vfov_degrees = desc.fisheye_fov_degrees * h / shorter;
        camera.m_pixel_angle = camera.m_radians_per_pixel_x;
        return camera;
    }
    if (desc.projection == Projection::Spherical) {
        // Equirectangular: longitude across the width (2π), latitude down the height (π).
        camera.m_radians_per_pixel_x = 2.0f * kPi / w;
        camera.m_radians_per_pixel_y = kPi / h;
        camera.m_hfov_degrees = 360.0f;
        camera.m_vfov_degrees = 180.0f;
        camera.m_pixel_angle = camera.m_radians_per_pixel_y;
        return camera;
    }

    // Window size from the field of view (seed 002: size = 2·dis·tan(fov/2)). With
    // fov_spans_pixel_centres the fov spans (n−1) pixels instead of n.
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
    camera.m_pixel_angle = 2.0f * std::tan(glm::radians(camera.m_vfov_degrees) / 2.0f) / h;

    // seed 002: CENTER = EYE + dis·VIEW;
    // ORIGIN = CENTER − ((width−1)/2)·hpixel·HORZ + ((height−1)/2)·vpixel·VERT, kept as
    // ORIGIN − EYE.
    camera.m_step_right = hpixel * camera.m_right;
    camera.m_step_down = vpixel * camera.m_up;
    camera.m_origin_from_eye = desc.distance * camera.m_view -
                               ((w - 1.0f) / 2.0f) * camera.m_step_right +
                               ((h - 1.0f) / 2.0f) * camera.m_step_down;
    return camera;
}

bool Camera::generate_other_ray(const glm::vec2& film, const glm::vec2& lens, Ray& ray) const {
    switch (m_desc.projection) {
        case Projection::Perspective: {
            // Thin lens (seed 004's extended pupil): every ray through film position `film`
            // passes the point where the pinhole ray meets the plane in focus, at
            // focus_distance along the view direction; its origin is the lens sample, mapped
            // to the lens disk (concentric map) in the plane of right and up through the eye.
            // window_from_eye has view component `distance` (the window plane). Both points
            // relative to the eye, as the pinhole's.
            const Vec3 in_focus = window_from_eye(film) * (m_focus_distance / m_desc.distance);
            const glm::vec2 disk = m_desc.lens_radius * concentric_disk(lens);
            const Vec3 on_lens = disk.x * m_right + disk.y * m_up;
            ray.origin = m_eye + on_lens;
            ray.direction = glm::normalize(in_focus - on_lens);
            return true;
        }
        case Projection::Fisheye: {
            // Equidistant: the angle from the view axis grows linearly with the distance from
            // the image centre, fov/2 on the rim of the image circle.
            const float dx = film.x - m_centre.x, dy = m_centre.y - film.y;
            const float r = std::sqrt(dx * dx + dy * dy);
            if (r > m_circle_radius) return false;
            const float theta = r * m_radians_per_pixel_x;
            const float sin_theta = std::sin(theta);
            const Vec3 radial = r > 0.0f ? (dx / r) * m_right + (dy / r) * m_up : Vec3(0.0f);
            ray.origin = m_eye;
            ray.direction = glm::normalize(std::cos(theta) * m_view + sin_theta * radial);
            return true;
        }
        case Projection::Spherical: {
            // Equirectangular: longitude 0 at the image centre (the view direction), −180° at
            // the left edge and +180° at the right; latitude +90° at the top edge.
            const float longitude = (film.x - m_centre.x) * m_radians_per_pixel_x;
            const float latitude = (m_centre.y - film.y) * m_radians_per_pixel_y;
            const float cos_latitude = std::cos(latitude);
            ray.origin = m_eye;
            ray.direction = glm::normalize(
                cos_latitude * (std::sin(longitude) * m_right + std::cos(longitude) * m_view) +
                std::sin(latitude) * m_up);
            return true;
        }
    }
    return false;
}

}  // namespace rayo
