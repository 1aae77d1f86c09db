#pragma once
// The seed 003 synthetic camera: a frame from the position p, the look-at point c and the sky
// vector s (eqs. 1.3–1.5), and the perspective projection of a point onto the window plane
// (eqs. 1.6–1.10), in the pixel coordinates of the ray-tracing camera (core/camera.h), so that
// a drawn line lands on the pixels whose rays see it (the preview, docs/preview.md).
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/line_clipping.h"

namespace rayo {

// Seed 003 eqs. 1.9, 1.10: the point where the line from the observer `o` through `q` meets the
// plane z = 0 (eqs. 1.6–1.8 with u = −o_z/(q_z − o_z)). Undefined for q_z = o_z.
DVec2 project_to_plane(const DVec3& q, const DVec3& o);

class SyntheticCamera {
  public:
    // The frame of eqs. 1.3–1.5 from position, look-at and sky, and the window of the seed 002
    // camera: the plane at `camera`'s distance along z, with its pixel size, so that
    // project() and Camera::generate_ray agree (film position (i, j) is pixel (i, j)'s centre).
    explicit SyntheticCamera(const Camera& camera);

    // seed 003 eq. 1.3: z = (c − p)/|c − p|; eq. 1.4: y = r/|r|, r = s − (s·z)z; eq. 1.5:
    // x = z × y (screen right in rayo's right-handed world, like the window camera's HORZ).
    const DVec3& x() const { return m_x; }
    const DVec3& y() const { return m_y; }
    const DVec3& z() const { return m_z; }

    // A world point in the camera frame: (x, y, z) components of point − p; z is the depth.
    DVec3 to_camera(const DVec3& point) const;
    // A camera-frame point with depth > 0 projected to film coordinates in pixels (x right,
    // y down, (i, j) the centre of pixel (i, j)): eqs. 1.9, 1.10 with the observer at
    // o = (0, 0, −distance) behind the window plane z = 0 of a frame centred on the window.
    DVec2 project_camera(const DVec3& q) const;
    DVec2 project(const DVec3& point) const { return project_camera(to_camera(point)); }

    // The window in film coordinates: the pixels' outer edges, [−½, width − ½] × [−½, height − ½].
    ClipRect window() const { return m_window; }
    // The angle one pixel subtends at the image centre (radians; the smaller side of a
    // non-square pixel): what outlines use to choose how finely to divide their curves.
    double pixel_angle() const { return m_pixel_angle; }
    const DVec3& position() const { return m_position; }

  private:
    DVec3 m_position{0.0}, m_x{0.0}, m_y{0.0}, m_z{0.0};
    double m_distance = 1.0;
    double m_hpixel = 1.0, m_vpixel = 1.0;      // window units per pixel, across and down
    double m_centre_x = 0.0, m_centre_y = 0.0;  // film position of the window centre
    ClipRect m_window;
    double m_pixel_angle = 0.0;
};

}  // namespace rayo
