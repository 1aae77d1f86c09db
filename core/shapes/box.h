#pragma once
// An axis-aligned box [min, max], closed (a solid for CSG). A Shape (core/shapes/shape.h);
// intersected by the slab method (Kay & Kajiya 1986): the ray is inside the box for t in
// [max of the entry distances, min of the exit distances].
#include <cstdint>
#include <optional>

#include "core/shapes/outline.h"
#include "core/shapes/shape.h"
#include "core/shapes/shape_fields.h"
#include "core/shapes/tessellation.h"

namespace rayo {

struct Box {
    Vec3 min{-1.0f};
    Vec3 max{1.0f};
    uint32_t material = 0;

    static constexpr const char* kName = "box";
    template <typename F>
    void fields(F& f) {
        f("min", min, FieldKind::Point);
        f("max", max, FieldKind::Point);
    }
    std::optional<FieldProblem> problem() const;
    Bounds3 bounds() const { return {min, max}; }
    int crossings(const Vec3& origin, const Vec3& direction,
                  ShapeCrossing out[kMaxShapeCrossings]) const;
    bool nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                 ShapeHit& hit) const;
    bool closed() const { return true; }
    void surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const;
    void parameterization(const Vec3& position, SurfaceHit& out) const;
    // The twelve edges.
    void outline(Outline& out) const;
    // Its surface as parametric pieces for tessellation (core/shapes/tessellation.h).
    void pieces(SurfacePieces& out) const;

    // The slab interval [t_enter, t_exit] and the faces' outward normals there; false when
    // the line misses the box.
    bool slabs(const Vec3& origin, const Vec3& direction, float& t_enter, Vec3& n_enter,
               float& t_exit, Vec3& n_exit) const;
};

}  // namespace rayo
