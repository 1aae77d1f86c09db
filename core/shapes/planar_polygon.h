#pragma once
// A planar polygon intersected directly, without triangles: the ray meets the polygon's plane,
// then a point-in-polygon test decides in a 2D projection (seed 004: "plane, then point in
// polygon: parity rule, winding number"). It is the other form of rayo's polygons, which are
// triangulated (core/shapes/polygon_triangulation.h) and handed to Embree as triangles; the two
// are compared in speed and memory by bench/polygon_point_in_polygon_bench.cpp (docs/nff.md,
// "Point in polygon against triangles").
#include <optional>
#include <vector>

#include "core/shapes/shape.h"

namespace rayo {

// Which points a self-intersecting outline covers. Both rules agree on simple polygons.
enum class FillRule {
    EvenOdd,         // parity: inside when a ray from the point crosses the outline an odd number
                     // of times (Jordan curve theorem)
    NonZeroWinding,  // inside when the outline winds around the point a non-zero number of times
};

class PlanarPolygon {
  public:
    // The polygon through `vertices` (their plane is the Newell plane, through their centroid),
    // or nothing when they enclose no area or a coordinate is not finite.
    static std::optional<PlanarPolygon> make(const std::vector<Vec3>& vertices, FillRule rule);

    // Whether the point (a, b), in the projection that drops the normal's largest component,
    // lies inside: Haines's crossing test for EvenOdd ("Point in Polygon Strategies", Graphics
    // Gems IV, 1994), Sunday's signed crossings for the winding number (his own "Inclusion of a
    // Point in a Polygon", 2001). Points on an edge fall on one side by the half-open rule (a
    // vertex on the test ray counts as above it).
    bool contains(float a, float b) const;
    // The projected coordinates `contains` takes of a point of the plane.
    void project(const Vec3& p, float& a, float& b) const;

    Bounds3 bounds() const { return m_bounds; }
    // The hit in (tnear, tfar) and the plane's unit normal (the Newell normal: the side from
    // which the vertices run counter-clockwise).
    bool nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                 ShapeHit& hit) const;

    const Vec3& normal() const { return m_normal; }
    size_t vertex_count() const { return m_a.size(); }
    // The heap and object bytes it holds (for the memory comparison with triangles).
    size_t bytes() const {
        return sizeof(*this) + (m_a.capacity() + m_b.capacity()) * sizeof(float);
    }

  private:
    Vec3 m_normal{0.0f};             // unit
    float m_offset = 0.0f;           // the plane is normal · p = offset
    int m_axis_a = 0, m_axis_b = 1;  // the kept world axes of the projection
    FillRule m_rule = FillRule::EvenOdd;
    std::vector<float> m_a, m_b;  // the projected vertices
    Bounds3 m_bounds;
};

}  // namespace rayo
