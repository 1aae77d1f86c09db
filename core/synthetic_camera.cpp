#include "core/synthetic_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace rayo {

DVec2 project_to_plane(const DVec3& q, const DVec3& o) {
    // seed 003 eqs. 1.9, 1.10 (the seed's CCamera::projection).
    const double denominator = q.z - o.z;
    return DVec2((o.x * q.z - q.x * o.z) / denominator, (o.y * q.z - q.y * o.z) / denominator);
}

SyntheticCamera::SyntheticCamera(const Camera& camera) {
    const CameraDesc& desc = camera.desc();
    m_position = DVec3(desc.eye);
    const DVec3 sky(desc.up);
    m_z = glm::normalize(DVec3(desc.look_at) - m_position);  // eq. 1.3
    const DVec3 r = sky - glm::dot(sky, m_z) * m_z;          // eq. 1.4
    m_y = glm::normalize(r);
    m_x = glm::cross(m_z, m_y);  // eq. 1.5
    m_distance = static_cast<double>(desc.distance);
    // The window camera's pixel size, from its field of view across the whole image (its
    // hfov/vfov span the image edges whichever NFF convention built it): size = 2·dis·tan(fov/2).
    const double w = camera.width(), h = camera.height();
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    m_hpixel = 2.0 * m_distance * std::tan(camera.hfov_degrees() * kDegree / 2.0) / w;
    m_vpixel = 2.0 * m_distance * std::tan(camera.vfov_degrees() * kDegree / 2.0) / h;
    // seed 002: pixel (0, 0) is ORIGIN = CENTER − ((w−1)/2)·hpixel·HORZ + ((h−1)/2)·vpixel·VERT.
    m_centre_x = (w - 1.0) / 2.0;
    m_centre_y = (h - 1.0) / 2.0;
    m_window = ClipRect{-0.5, -0.5, w - 0.5, h - 0.5};
    m_pixel_angle = std::min(m_hpixel, m_vpixel) / m_distance;  // the finer, for non-square pixels
}

DVec3 SyntheticCamera::to_camera(const DVec3& point) const {
    const DVec3 v = point - m_position;
    return DVec3(glm::dot(v, m_x), glm::dot(v, m_y), glm::dot(v, m_z));
}

DVec2 SyntheticCamera::project_camera(const DVec3& q) const {
    // Shift the frame to the window centre (depth `distance`); the observer (the eye) is then
    // at o = (0, 0, −distance) and the window is the plane z = 0 of eqs. 1.9, 1.10.
    const DVec2 on_window =
        project_to_plane(DVec3(q.x, q.y, q.z - m_distance), DVec3(0.0, 0.0, -m_distance));
    return DVec2(m_centre_x + on_window.x / m_hpixel, m_centre_y - on_window.y / m_vpixel);
}

}  // namespace rayo
