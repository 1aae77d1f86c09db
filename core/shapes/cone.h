#pragma once
// NFF open cones and cylinders (`c`): the surface between a base circle and an apex circle,
// no caps. Radius varies linearly along the axis; a cylinder has equal radii.
#include <cstdint>
#include <optional>

#include "core/math.h"
#include "core/shapes/outline.h"
#include "core/shapes/shape.h"
#include "core/shapes/shape_fields.h"
#include "core/shapes/tessellation.h"

namespace rayo {

// What the intersection needs of a cone, computed once per cone rather than per ray: the cone's
// Intersector (core/shapes/shape.h).
struct ConeFrame {
    DVec3 base{0.0};
    DVec3 axis{0.0, 1.0, 0.0};  // unit, base -> apex
    double height = 0.0;        // 0: degenerate, never hit
    double base_radius = 0.0;
    double slope = 0.0;  // dr/ds along the axis

    bool nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                 ShapeHit& hit) const;
    int crossings(const Vec3& origin, const Vec3& direction,
                  ShapeCrossing out[kMaxShapeCrossings]) const;
};

// A Shape (core/shapes/shape.h).
struct Cone {
    Vec3 base{0.0f};
    float base_radius = 1.0f;
    Vec3 apex{0.0f, 1.0f, 0.0f};
    float apex_radius = 1.0f;
    uint32_t material = 0;

    static constexpr const char* kName = "cone";
    template <typename F>
    void fields(F& f) {
        f("base", base, FieldKind::Point);
        f("base_radius", base_radius, FieldKind::NonNegative);
        f("apex", apex, FieldKind::Point);
        f("apex_radius", apex_radius, FieldKind::NonNegative);
    }
    std::optional<FieldProblem> problem() const;
    using Intersector = ConeFrame;
    ConeFrame intersector() const;
    Bounds3 bounds() const;
    int crossings(const Vec3& origin, const Vec3& direction,
                  ShapeCrossing out[kMaxShapeCrossings]) const {
        return intersector().crossings(origin, direction, out);
    }
    void surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const;
    void parameterization(const Vec3& position, SurfaceHit& out) const;
    // Both rims and the two generators along which rays from the eye graze the surface.
    void outline(Outline& out) const;
    // Its surface as parametric pieces for tessellation (core/shapes/tessellation.h).
    void pieces(SurfacePieces& out) const;
};

ConeFrame make_cone_frame(const Cone& cone);

// Tight axis-aligned bounds: each end circle extends r·√(1 − a_i²) along world axis i.
void cone_bounds(const Cone& cone, Vec3& lower, Vec3& upper);

// Nearest hit in (tnear, tfar) of a ray (unit direction) with the open cone; the outward normal
// at the hit goes to `normal`. Solves |w⊥ + t·d⊥|² = (r(s))², s the axial coordinate, in double.
bool intersect_cone(const ConeFrame& cone, const Vec3& origin, const Vec3& direction, float tnear,
                    float tfar, float& t_out, Vec3& normal);
inline bool intersect_cone(const Cone& cone, const Vec3& origin, const Vec3& direction, float tnear,
                           float tfar, float& t_out, Vec3& normal) {
    return intersect_cone(make_cone_frame(cone), origin, direction, tnear, tfar, t_out, normal);
}

}  // namespace rayo
