#include "core/shapes/polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace rayo {
namespace {

// A turn to the right by less than this sine still counts as straight when testing convexity:
// the collinear vertices of a tessellated outline, computed in float, may turn right by rounding
// alone; a fan over such a polygon is still correct to that rounding.
constexpr double kConvexSineTolerance = 1e-6;

struct Point2 {
    double x, y;
};

// Twice the signed area of the triangle abc: > 0 when a, b, c run counter-clockwise.
double signed_area2(const Point2& a, const Point2& b, const Point2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool same_point(const Point2& a, const Point2& b) {
    return a.x == b.x && a.y == b.y;
}

double largest_coordinate(const std::vector<Vec3>& vertices) {
    double largest = 0.0;
    for (const Vec3& v : vertices) largest = std::max(largest, double(max_abs_component(v)));
    return largest;
}

// Projects the vertices onto the plane through vertex 0 perpendicular to `normal`, in a basis
// (u, v) with u × v = normal / |normal|: counter-clockwise about the normal stays
// counter-clockwise in the plane.
std::vector<Point2> project(const std::vector<Vec3>& vertices, const DVec3& normal) {
    const DVec3 n = glm::normalize(normal);
    const DVec3 abs_n = glm::abs(n);
    // Start u from the axis least aligned with the normal, so the cross product is well sized.
    const DVec3 axis = abs_n.x <= abs_n.y && abs_n.x <= abs_n.z ? DVec3(1, 0, 0)
                       : abs_n.y <= abs_n.z                     ? DVec3(0, 1, 0)
                                                                : DVec3(0, 0, 1);
    const DVec3 u = glm::normalize(glm::cross(axis, n));
    const DVec3 v = glm::cross(n, u);
    const DVec3 origin(vertices[0]);
    std::vector<Point2> points;
    points.reserve(vertices.size());
    for (const Vec3& p : vertices) {
        const DVec3 d = DVec3(p) - origin;
        points.push_back({glm::dot(d, u), glm::dot(d, v)});
    }
    return points;
}

// Convex and counter-clockwise: no turn to the right, no reversal (a spike), and the turns add up
// to one trip around (a pentagram turns left everywhere, twice). Repeated vertices are passed
// over, so that the turn at a repeated corner is measured between its real edges. A turn counts
// as straight within the rounding of float input: a sine of 1e-6, or a cross product that moving
// the corner by a few float ulps of the polygon's largest coordinate (`ulp_scale`) could undo.
bool convex_counter_clockwise(const std::vector<Point2>& points, double ulp_scale) {
    std::vector<Point2> q;
    for (const Point2& p : points) {
        if (q.empty() || !same_point(p, q.back())) q.push_back(p);
    }
    while (q.size() > 1 && same_point(q.front(), q.back())) q.pop_back();
    const size_t n = q.size();
    if (n < 3) return false;
    const double shift = 4.0 * ulp_scale * std::numeric_limits<float>::epsilon();
    double turning = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const Point2& a = q[(i + n - 1) % n];
        const Point2& b = q[i];
        const Point2& c = q[(i + 1) % n];
        const Point2 e1{b.x - a.x, b.y - a.y}, e2{c.x - b.x, c.y - b.y};
        const double l1 = std::hypot(e1.x, e1.y), l2 = std::hypot(e2.x, e2.y);
        const double cross = e1.x * e2.y - e1.y * e2.x;
        const double dot = e1.x * e2.x + e1.y * e2.y;
        const double tolerance = std::max(kConvexSineTolerance * l1 * l2, shift * (l1 + l2));
        if (cross < -tolerance) return false;                         // turns right
        if (dot < 0.0 && std::abs(cross) <= tolerance) return false;  // reverses
        turning += std::atan2(cross, dot);
    }
    return turning < 3.0 * M_PI;  // 2π for a simple convex outline, 4π and more when it winds
}

// Ear clipping (Meisters' two-ears theorem; the vertex list is counter-clockwise): a vertex is
// an ear when it turns left and no other remaining vertex that is reflex or straight lies in or
// on the triangle it forms with its neighbours (if any vertex lay inside, a reflex one would).
class EarClipper {
  public:
    explicit EarClipper(const std::vector<Point2>& points)
        : m_q(points),
          m_prev(points.size()),
          m_next(points.size()),
          m_removed(points.size(), 0),
          m_reflex(points.size(), 0) {
        const auto n = static_cast<uint32_t>(points.size());
        for (uint32_t i = 0; i < n; ++i) {
            m_prev[i] = (i + n - 1) % n;
            m_next[i] = (i + 1) % n;
        }
        for (uint32_t i = 0; i < n; ++i) update_reflex(i);
    }

    std::vector<PolygonTriangle> run() {
        std::vector<PolygonTriangle> triangles;
        triangles.reserve(m_q.size() - 2);
        size_t remaining = m_q.size();
        uint32_t i = 0;
        size_t since_last_clip = 0;
        while (remaining > 3) {
            if (turn(i) == 0.0 || is_ear(i)) {
                // A straight vertex (collinear with its neighbours, or a spike) is clipped as a
                // zero-area triangle: the outline keeps its shape without it.
                const uint32_t following = m_next[i];
                clip(i, triangles);
                --remaining;
                i = following;
                since_last_clip = 0;
                continue;
            }
            i = m_next[i];
            if (++since_last_clip >= remaining) {
                // No ear in a whole round: only for self-intersecting outlines or rounding at
                // near-touching vertices. Clip the most convex vertex so that the loop ends.
                uint32_t best = i;
                for (size_t k = 0; k < remaining; ++k, i = m_next[i]) {
                    if (turn(i) > turn(best)) best = i;
                }
                const uint32_t following = m_next[best];
                clip(best, triangles);
                --remaining;
                i = following;
                since_last_clip = 0;
            }
        }
        triangles.push_back({m_prev[i], i, m_next[i]});
        return triangles;
    }

  private:
    // Twice the signed area of (prev, i, next): > 0 for a left (convex) turn.
    double turn(uint32_t i) const { return signed_area2(m_q[m_prev[i]], m_q[i], m_q[m_next[i]]); }

    void update_reflex(uint32_t i) {
        if (turn(i) <= 0.0 && !m_reflex[i]) {
            m_reflex[i] = 1;
            m_reflex_list.push_back(i);
        } else if (turn(i) > 0.0) {
            m_reflex[i] = 0;  // stays in m_reflex_list, skipped there
        }
    }

    bool is_ear(uint32_t i) const {
        if (!(turn(i) > 0.0)) return false;
        const uint32_t a = m_prev[i], c = m_next[i];
        const Point2 &pa = m_q[a], &pi = m_q[i], &pc = m_q[c];
        for (const uint32_t r : m_reflex_list) {
            if (m_removed[r] || !m_reflex[r] || r == a || r == i || r == c) continue;
            const Point2& p = m_q[r];
            // A vertex repeated at an ear corner (outlines that touch themselves) does not block.
            if (same_point(p, pa) || same_point(p, pi) || same_point(p, pc)) continue;
            if (signed_area2(pa, pi, p) >= 0.0 && signed_area2(pi, pc, p) >= 0.0 &&
                signed_area2(pc, pa, p) >= 0.0) {
                return false;
            }
        }
        return true;
    }

    void clip(uint32_t i, std::vector<PolygonTriangle>& triangles) {
        const uint32_t a = m_prev[i], c = m_next[i];
        triangles.push_back({a, i, c});  // the polygon's own order: its winding
        m_next[a] = c;
        m_prev[c] = a;
        m_removed[i] = 1;
        // Clipping an ear only sharpens its neighbours' angles, but clipping a spike can turn a
        // neighbour around: recompute both.
        update_reflex(a);
        update_reflex(c);
    }

    const std::vector<Point2>& m_q;
    std::vector<uint32_t> m_prev, m_next;
    std::vector<char> m_removed, m_reflex;
    std::vector<uint32_t> m_reflex_list;  // every vertex that was ever reflex or straight
};

}  // namespace

std::string polygon_vertex_limit_text(size_t count) {
    return "polygon of " + std::to_string(count) + " vertices; the limit is " +
           std::to_string(kMaxPolygonVertices) +
           " (triangulation takes time quadratic in the count)";
}

DVec3 newell_normal(const std::vector<Vec3>& vertices) {
    // Newell's method (Sutherland, Sproull & Schumacker 1974): the sum of the edges' cross
    // products, taken relative to vertex 0 so that far-away polygons keep their precision.
    DVec3 normal(0.0);
    if (vertices.empty()) return normal;
    const DVec3 origin(vertices[0]);
    for (size_t i = 0; i < vertices.size(); ++i) {
        const DVec3 a = DVec3(vertices[i]) - origin;
        const DVec3 b = DVec3(vertices[(i + 1) % vertices.size()]) - origin;
        normal += glm::cross(a, b);
    }
    return normal;
}

bool is_convex_polygon(const std::vector<Vec3>& vertices) {
    if (vertices.size() < 3) return false;
    const DVec3 normal = newell_normal(vertices);
    if (!(glm::length(normal) > 0.0)) return false;
    return convex_counter_clockwise(project(vertices, normal), largest_coordinate(vertices));
}

std::vector<PolygonTriangle> triangulate_polygon(const std::vector<Vec3>& vertices) {
    if (vertices.size() < 3) return {};
    const DVec3 normal = newell_normal(vertices);
    if (!(glm::length(normal) > 0.0)) return {};  // no area (or a non-finite coordinate)
    const std::vector<Point2> points = project(vertices, normal);
    if (convex_counter_clockwise(points, largest_coordinate(vertices))) {
        std::vector<PolygonTriangle> fan;
        fan.reserve(vertices.size() - 2);
        for (uint32_t i = 1; i + 1 < vertices.size(); ++i) fan.push_back({0, i, i + 1});
        return fan;
    }
    return EarClipper(points).run();
}

}  // namespace rayo
