#include "core/shapes/outline.h"

#include <algorithm>
#include <cmath>

namespace rayo {

void perpendicular_frame(const DVec3& n, DVec3& u, DVec3& v) {
    // Cross with the world axis least aligned with n.
    const DVec3 a = std::abs(n.x) < 0.5 ? DVec3(1, 0, 0)
                                        : (std::abs(n.y) < 0.5 ? DVec3(0, 1, 0) : DVec3(0, 0, 1));
    u = glm::normalize(glm::cross(n, a));
    v = glm::cross(n, u);
}

int Outline::circle_chords(double radius, double distance) const {
    // Seen from `distance`, the circle's radius spans radius_px pixels; a chord of a circle of
    // radius R over the angle 2π/N lies R(1 − cos(π/N)) inside it (its sagitta).
    const double radius_px = radius / (std::max(distance, 1e-12 * radius) * m_view.pixel_angle);
    if (!(radius_px > kMaxSagittaPixels)) return kMinChords;
    const double half_angle = std::acos(1.0 - kMaxSagittaPixels / radius_px);
    const double chords = std::ceil(3.14159265358979323846 / half_angle);
    return static_cast<int>(std::clamp(chords, double(kMinChords), double(kMaxChords)));
}

void Outline::add_circle(const DVec3& center, const DVec3& normal, double radius) {
    if (!(radius > 0.0)) return;
    const double distance = glm::length(center - m_view.eye) - radius;
    const int chords = circle_chords(radius, distance);
    DVec3 u, v;
    perpendicular_frame(normal, u, v);
    const double step = 2.0 * 3.14159265358979323846 / chords;
    DVec3 previous = center + radius * u;
    for (int i = 1; i <= chords; ++i) {
        const double angle = i * step;
        const DVec3 next = i == chords
                               ? center + radius * u
                               : center + radius * (std::cos(angle) * u + std::sin(angle) * v);
        add_segment(previous, next);
        previous = next;
    }
}

}  // namespace rayo
