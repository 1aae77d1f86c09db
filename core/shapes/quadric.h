#pragma once
// The general quadric A·x² + B·y² + C·z² + D·xy + E·xz + F·yz + G·x + H·y + I·z + J = 0 clipped
// to an axis-aligned box: the solid where the left side is <= 0 within `bounds` (its outward
// normal is the gradient, toward positive values). Seed 004 names the quadrics but gives no
// coefficient order (its equations are lost from the text); `coefficients` follows the order
// above, the one of the issue. A Shape (core/shapes/shape.h) through a ClippedQuadric
// (core/shapes/clipped_quadric.h).
#include <array>
#include <cstdint>
#include <optional>

#include "core/shapes/clipped_quadric.h"
#include "core/shapes/shape_fields.h"

namespace rayo {

struct Quadric : QuadricShape<Quadric> {
    // A B C D E F G H I J, in double: world-space coefficients of a shape far from the origin
    // differ by many orders of magnitude (docs/stability.md, "Quadrics").
    std::array<double, 10> coefficients{};
    Bounds3 clip{Vec3(-1.0f), Vec3(1.0f)};
    bool capped = true;  // false: the box faces are not surface (an open, clipped quadric)
    uint32_t material = 0;

    static constexpr const char* kName = "quadric";
    template <typename F>
    void fields(F& f) {
        f("coefficients", coefficients, FieldKind::Numbers);
        f("bounds", clip, FieldKind::Box);
        f.optional("capped", capped, FieldKind::Flag);
    }
    std::optional<FieldProblem> problem() const;
    ClippedQuadric intersector() const;
    // The edges of the clip box (a general quadric's silhouette is not drawn).
    void outline(Outline& out) const { intersector().add_box_edges(out); }
    // None: a general quadric clipped to a box is not tessellated (docs/radiosity.md, "Choices
    // and limits"); the radiosity solve warns and leaves it out.
    void pieces(SurfacePieces&) const {}
};

}  // namespace rayo
