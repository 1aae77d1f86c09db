#pragma once
// Named quadrics, each a Shape (core/shapes/shape.h) whose intersector is a ClippedQuadric
// (core/shapes/clipped_quadric.h) in the shape's own frame: local z along `axis`, the quadric in
// its standard form there, clipped to a local box. Capped forms are closed solids: the box faces
// cut discs from them (a cylinder's caps are those discs), so CSG can use them; `capped` false
// leaves the surface open. Every form is scaled so its coefficients are of order 1.
//
//   ellipsoid    (x/a)² + (y/b)² + (z/c)² − 1 = 0            radii (a, b, c), world axes
//   cylinder     (x² + y²)/r² − 1 = 0, 0 <= z <= h           base, top (h = |top − base|)
//   paraboloid   (x² + y²)/r² − z/h = 0, z <= h              vertex, axis, radius r at height h
//   hyperboloid  (x² + y²)/a² − (z/c)² ∓ 1 = 0, |z| <= h/2   center, axis, radius a, semi_axis c;
//                −1: one sheet (waist radius a), +1: two sheets (vertices at z = ±c)
#include <cstdint>
#include <optional>

#include "core/shapes/clipped_quadric.h"
#include "core/shapes/shape_fields.h"

namespace rayo {

struct Ellipsoid : QuadricShape<Ellipsoid> {
    Vec3 center{0.0f};
    Vec3 radii{1.0f};
    uint32_t material = 0;

    static constexpr const char* kName = "ellipsoid";
    template <typename F>
    void fields(F& f) {
        f("center", center, FieldKind::Point);
        f("radii", radii, FieldKind::Point);
    }
    std::optional<FieldProblem> problem() const;
    ClippedQuadric intersector() const;
    // The three principal ellipses.
    void outline(Outline& out) const;
    // Its surface as parametric pieces for tessellation (core/shapes/tessellation.h).
    void pieces(SurfacePieces& out) const;
};

struct Cylinder : QuadricShape<Cylinder> {
    Vec3 base{0.0f};             // centre of the bottom cap
    Vec3 top{0.0f, 1.0f, 0.0f};  // centre of the top cap
    float radius = 1.0f;
    bool capped = true;
    uint32_t material = 0;

    static constexpr const char* kName = "cylinder";
    template <typename F>
    void fields(F& f) {
        f("base", base, FieldKind::Point);
        f("top", top, FieldKind::Point);
        f("radius", radius, FieldKind::Positive);
        f.optional("capped", capped, FieldKind::Flag);
    }
    std::optional<FieldProblem> problem() const;
    ClippedQuadric intersector() const;
    // Both rims and four generators.
    void outline(Outline& out) const;
    // Its surface as parametric pieces for tessellation (core/shapes/tessellation.h).
    void pieces(SurfacePieces& out) const;
};

struct Paraboloid : QuadricShape<Paraboloid> {
    Vec3 vertex{0.0f};
    Vec3 axis{0.0f, 1.0f, 0.0f};  // unit, into the bowl
    float radius = 1.0f;          // at `height` from the vertex
    float height = 1.0f;
    bool capped = true;
    uint32_t material = 0;

    static constexpr const char* kName = "paraboloid";
    template <typename F>
    void fields(F& f) {
        f("vertex", vertex, FieldKind::Point);
        f.optional("axis", axis, FieldKind::Direction);
        f("radius", radius, FieldKind::Positive);
        f("height", height, FieldKind::Positive);
        f.optional("capped", capped, FieldKind::Flag);
    }
    std::optional<FieldProblem> problem() const { return std::nullopt; }
    ClippedQuadric intersector() const;
    // The rim and four profile parabolas.
    void outline(Outline& out) const;
    // Its surface as parametric pieces for tessellation (core/shapes/tessellation.h).
    void pieces(SurfacePieces& out) const;
};

struct Hyperboloid : QuadricShape<Hyperboloid> {
    Vec3 center{0.0f};
    Vec3 axis{0.0f, 1.0f, 0.0f};  // unit
    float radius = 1.0f;          // a
    float semi_axis = 1.0f;       // c
    float height = 2.0f;          // the extent along the axis, centred on `center`
    int sheets = 1;
    bool capped = true;
    uint32_t material = 0;

    static constexpr const char* kName = "hyperboloid";
    template <typename F>
    void fields(F& f) {
        f("center", center, FieldKind::Point);
        f.optional("axis", axis, FieldKind::Direction);
        f("radius", radius, FieldKind::Positive);
        f("semi_axis", semi_axis, FieldKind::Positive);
        f("height", height, FieldKind::Positive);
        f.optional("sheets", sheets, FieldKind::Integer);
        f.optional("capped", capped, FieldKind::Flag);
    }
    std::optional<FieldProblem> problem() const;
    ClippedQuadric intersector() const;
    // The end rims (and the waist of one sheet) and four profile hyperbolas.
    void outline(Outline& out) const;
    // Its surface as parametric pieces for tessellation (core/shapes/tessellation.h).
    void pieces(SurfacePieces& out) const;
    // The radius at axial distance z from the centre.
    double radius_at(double z) const;
};

}  // namespace rayo
