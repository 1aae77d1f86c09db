#pragma once
// Blobs (metaballs): the implicit surface F(p) = threshold of a sum of compactly supported
// radial fields, one per element,
//   F(p) = Σ s_i·K(|p − c_i|² / R_i²),   K(u) = (1 − u)³ for u < 1, else 0,
// the solid being F > threshold. K is a polynomial in r² (no square root) that falls from 1 at
// the centre to 0 at the support radius R with zero first and second derivatives there, so
// blended elements meet smoothly: the "soft object" family of Wyvill, McPheeters & Wyvill 1986
// ("Data structure for soft objects"), in the cubic form that Müller, Charypar & Gross 2003 call
// poly6. A lone element of strength s > threshold T is the sphere of radius
//   ρ = R·√(1 − ∛(T/s)).
// Negative strengths subtract.
//
// Intersection (seed 004: "implicit surfaces by Newton's method or by searching for a sign
// change of F along the ray"): along the ray each element's term is a function of
// u(t) = ((t − t_c)² + h²)/R², whose range over an interval of t is exact (u is monotone on each
// side of t_c, K is monotone in u), and so is the range of its t-derivative; their sums bound
// F − T and F' over the interval (interval arithmetic, Mitchell 1990, "Robust ray intersection
// with interval arithmetic"). An interval whose bound excludes 0 holds no surface; one where F'
// keeps its sign holds at most one crossing, which a sign change of F at its ends brackets and
// Newton's method refines (falling back to bisection when a step leaves the bracket); any other
// interval is halved. No crossing is missed for want of samples, so grazing rays neither miss
// nor speckle; two crossings closer than kBlobResolution of the span merge (a tangent touch).
#include <cstdint>
#include <optional>
#include <vector>

#include "core/shapes/outline.h"
#include "core/shapes/shape.h"
#include "core/shapes/shape_fields.h"
#include "core/shapes/tessellation.h"

namespace rayo {

struct BlobElement {
    Vec3 center{0.0f};
    float radius = 1.0f;    // R: the field's support
    float strength = 1.0f;  // s: the field at the centre

    template <typename F>
    void fields(F& f) {
        f("center", center, FieldKind::Point);
        f("radius", radius, FieldKind::Positive);
        f("strength", strength, FieldKind::Number);
    }
    std::optional<FieldProblem> problem() const { return std::nullopt; }
};

// Elements per blob: the ray's active elements are kept on the stack.
constexpr int kMaxBlobElements = 128;

struct Blob {
    std::vector<BlobElement> elements{BlobElement{}};  // the scene file gives them all
    float threshold = 0.5f;
    uint32_t material = 0;

    static constexpr const char* kName = "blob";
    template <typename F>
    void fields(F& f) {
        f("elements", elements, FieldKind::Records);
        f("threshold", threshold, FieldKind::Positive);
    }
    std::optional<FieldProblem> problem() const;
    // The union of the positive elements' support boxes (F <= 0 < T outside them).
    Bounds3 bounds() const;
    bool closed() const { return true; }
    // The CSG budget (core/shapes/csg.h): one inside interval per element.
    int max_crossings() const { return 2 * static_cast<int>(elements.size()); }
    int crossings(const Vec3& origin, const Vec3& direction,
                  ShapeCrossing out[kMaxShapeCrossings]) const {
        return crossings(origin, direction, out, kMaxShapeCrossings);
    }
    // At most `capacity` crossings, the nearest ones.
    int crossings(const Vec3& origin, const Vec3& direction, ShapeCrossing* out,
                  int capacity) const;
    bool nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                 ShapeHit& hit) const;
    void surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const;
    // Spherical coordinates about the centre of the bounds.
    void parameterization(const Vec3& position, SurfaceHit& out) const;
    // Each element's sphere alone (its silhouette), for elements stronger than the threshold.
    void outline(Outline& out) const;
    // None: a blob is not tessellated for the radiosity solve (docs/radiosity.md, "Choices
    // and limits"); the solve warns and leaves it out (it still occludes).
    void pieces(SurfacePieces&) const {}

    // F at a point and its gradient (for tests and normals).
    double field(const DVec3& p) const;
    DVec3 gradient(const DVec3& p) const;
    // The radius of a lone element's sphere (0 when s <= T).
    static double sphere_radius(const BlobElement& e, double threshold);
};

}  // namespace rayo
