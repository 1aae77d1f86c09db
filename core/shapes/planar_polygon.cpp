#include "core/shapes/planar_polygon.h"

#include <cmath>

#include "core/shapes/polygon_triangulation.h"

namespace rayo {

std::optional<PlanarPolygon> PlanarPolygon::make(const std::vector<Vec3>& vertices, FillRule rule) {
    if (vertices.size() < 3) return std::nullopt;
    for (const Vec3& v : vertices) {
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return std::nullopt;
    }
    const DVec3 newell = newell_normal(vertices);
    const double length = glm::length(newell);
    if (!(length > 0.0)) return std::nullopt;
    PlanarPolygon polygon;
    polygon.m_rule = rule;
    const DVec3 n = newell / length;
    polygon.m_normal = Vec3(n);
    DVec3 centroid(0.0);
    for (const Vec3& v : vertices) centroid += DVec3(v);
    centroid /= double(vertices.size());
    polygon.m_offset = float(glm::dot(n, centroid));
    // Drop the axis along which the normal is largest: the projection onto the other two is
    // one-to-one on the plane and shrinks areas the least.
    const DVec3 abs_n = glm::abs(n);
    const int dropped = abs_n.x >= abs_n.y && abs_n.x >= abs_n.z ? 0 : abs_n.y >= abs_n.z ? 1 : 2;
    polygon.m_axis_a = (dropped + 1) % 3;
    polygon.m_axis_b = (dropped + 2) % 3;
    polygon.m_bounds = {vertices[0], vertices[0]};
    for (const Vec3& v : vertices) {
        polygon.m_a.push_back(v[polygon.m_axis_a]);
        polygon.m_b.push_back(v[polygon.m_axis_b]);
        polygon.m_bounds.lower = glm::min(polygon.m_bounds.lower, v);
        polygon.m_bounds.upper = glm::max(polygon.m_bounds.upper, v);
    }
    // A polygon that is not exactly planar in float: widen the box by the largest distance of a
    // vertex from the plane, so that every hit on the plane within the outline is inside it.
    float off_plane = 0.0f;
    for (const Vec3& v : vertices) {
        off_plane = std::max(off_plane, std::abs(glm::dot(polygon.m_normal, v) - polygon.m_offset));
    }
    const Vec3 margin(off_plane +
                      1e-6f * max_abs_component(polygon.m_bounds.upper - polygon.m_bounds.lower));
    polygon.m_bounds.lower -= margin;
    polygon.m_bounds.upper += margin;
    return polygon;
}

void PlanarPolygon::project(const Vec3& p, float& a, float& b) const {
    a = p[m_axis_a];
    b = p[m_axis_b];
}

bool PlanarPolygon::contains(float a, float b) const {
    const size_t n = m_a.size();
    if (m_rule == FillRule::EvenOdd) {
        // Crossing test: a ray from (a, b) toward +a; an edge that straddles the line b' = b
        // (half-open: one end strictly above, the other not) and meets it right of the point
        // toggles inside.
        bool inside = false;
        for (size_t i = 0, j = n - 1; i < n; j = i++) {
            const bool above_i = m_b[i] > b, above_j = m_b[j] > b;
            if (above_i == above_j) continue;
            const float crossing_a = m_a[i] + (b - m_b[i]) * (m_a[j] - m_a[i]) / (m_b[j] - m_b[i]);
            if (a < crossing_a) inside = !inside;
        }
        return inside;
    }
    // Winding number: upward edges with the point on their left count +1, downward edges with
    // the point on their right −1 (the same half-open straddle rule).
    int winding = 0;
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const bool above_i = m_b[i] > b, above_j = m_b[j] > b;
        if (above_i == above_j) continue;
        // Twice the signed area of (j, i, point): > 0 when the point is left of the edge j → i.
        const float side = (m_a[i] - m_a[j]) * (b - m_b[j]) - (a - m_a[j]) * (m_b[i] - m_b[j]);
        if (above_i && side > 0.0f)
            ++winding;  // upward edge, point on its left
        else if (!above_i && side < 0.0f)
            --winding;  // downward edge, point on its right
    }
    return winding != 0;
}

bool PlanarPolygon::nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                            ShapeHit& hit) const {
    const float denominator = glm::dot(m_normal, direction);
    if (denominator == 0.0f) return false;
    const float t = (m_offset - glm::dot(m_normal, origin)) / denominator;
    if (!(t > tnear && t < tfar)) return false;
    const Vec3 p = origin + t * direction;
    if (!contains(p[m_axis_a], p[m_axis_b])) return false;
    hit.t = t;
    hit.normal = m_normal;
    hit.part = 0;
    return true;
}

}  // namespace rayo
