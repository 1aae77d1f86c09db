#pragma once
// A flat disk: the points of the plane through `center` with normal `normal` within `radius` of
// the centre. Two-sided (its outward normal is `normal`; the integrator faces it to the ray).
// A Shape (core/shapes/shape.h); needed later as the lens of the thin-lens camera, the emitter of
// disk area lights and the caps of cylinders.
#include <cstdint>
#include <optional>

#include "core/shapes/outline.h"
#include "core/shapes/shape.h"
#include "core/shapes/shape_fields.h"
#include "core/shapes/tessellation.h"

namespace rayo {

struct Disk {
    Vec3 center{0.0f};
    Vec3 normal{0.0f, 1.0f, 0.0f};  // unit
    float radius = 1.0f;
    uint32_t material = 0;

    static constexpr const char* kName = "disk";
    template <typename F>
    void fields(F& f) {
        f("center", center, FieldKind::Point);
        f.optional("normal", normal, FieldKind::Direction);
        f("radius", radius, FieldKind::Positive);
    }
    std::optional<FieldProblem> problem() const { return std::nullopt; }
    Bounds3 bounds() const;
    int crossings(const Vec3& origin, const Vec3& direction,
                  ShapeCrossing out[kMaxShapeCrossings]) const;
    bool nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                 ShapeHit& hit) const;
    void surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const;
    void parameterization(const Vec3& position, SurfaceHit& out) const;
    // The rim.
    void outline(Outline& out) const;
    // Its surface as parametric a piece for tessellation (core/shapes/tessellation.h).
    void pieces(SurfacePieces& out) const;
};

}  // namespace rayo
