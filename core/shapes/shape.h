#pragma once
// The Shape concept: what an analytic shape provides so that one generic pair of Embree
// user-geometry callbacks (core/user_geometry.h) can trace it, CSG can combine it and the shader
// can light it (docs/architecture.md, "Extension points"). A shape type S is a plain struct with
// its parameters, `uint32_t material`, and:
//
//   static constexpr const char* kName;       // its name in scene files ("sphere", "disk", ...)
//   template <typename F> void fields(F& f);  // its scene-file fields (core/shapes/shape_fields.h)
//   std::optional<FieldProblem> problem() const;  // what is wrong with it, after the fields
//   Bounds3 bounds() const;
//   int crossings(const Vec3& o, const Vec3& d, ShapeCrossing out[kMaxShapeCrossings]) const;
//       // every crossing of the line o + t·d (any t), sorted by t, entering or leaving, with
//       // the outward normal there
//   bool closed() const;  // optional: true when the shape bounds a solid (CSG takes only
//       // closed shapes as children: core/shapes/csg.h); a shape without it is open
//   bool nearest(const Vec3& o, const Vec3& d, float tnear, float tfar, ShapeHit& hit) const;
//       // the first crossing in (tnear, tfar) and the outward normal there: the hot path
//   void surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const;
//       // position, unit outward geometric and shading normals, object size
//   void parameterization(const Vec3& position, SurfaceHit& out) const;  // uv and dpdu
//   void outline(Outline& out) const;  // its lines seen from out.view().eye: the wireframe
//       // preview (core/shapes/outline.h)
//   void pieces(SurfacePieces& out) const;  // its surface as parametric pieces: tessellation
//       // for the radiosity solve (core/shapes/tessellation.h); none for the general quadric
//
// Directions are unit length. A shape whose intersection wants per-shape precomputation names
// it `using Intersector = ...; Intersector intersector() const;` (the cone's frame); otherwise
// the shape is its own intersector (ShapeTraits below).
#include <cstdint>
#include <type_traits>

#include "core/ray.h"
#include "core/surface_hit.h"

namespace rayo {

struct Bounds3 {
    Vec3 lower{0.0f};
    Vec3 upper{0.0f};
};

// A crossing of a ray's line with a shape's surface; `entering` when the ray goes from outside
// to inside there (for open surfaces: against the outward normal); `normal` is the outward
// normal there (any length), what CSG reports when the crossing bounds its result.
struct ShapeCrossing {
    float t = 0.0f;
    bool entering = true;
    Vec3 normal{0.0f};
};
// A quadric solid clipped to a box (core/shapes/clipped_quadric.h) has the most: two inside
// intervals of the quadric (a hyperboloid along its axis) within the box's one.
constexpr int kMaxShapeCrossings = 4;

// What the intersection reports: the distance, and a normal at the hit (any length, outward)
// that surface() may use instead of recomputing it. `part` is for aggregate primitives (the
// brute-force spheres: one Embree primitive, every sphere a part): it is added to the primitive
// id reported to Embree.
struct ShapeHit {
    float t = 0.0f;
    Vec3 normal{0.0f};
    uint32_t part = 0;
};

// The unit outward normal of a hit from the normal the intersection reported (any length); a
// zero one (a singular point of the surface) faces the ray instead.
inline Vec3 unit_normal_or_facing(const Vec3& normal, const Vec3& ray_direction) {
    const float length_squared = glm::dot(normal, normal);
    return length_squared > 0.0f ? normal * glm::inversesqrt(length_squared) : -ray_direction;
}

// surface() of a shape whose intersection reports the normal and whose hit is the ray's point
// (CSG, blobs): unit normals from hit.normal, the bounds' largest side as the object size.
inline void surface_at_ray_point(const Ray& ray, const ShapeHit& hit, const Bounds3& bounds,
                                 SurfaceHit& out) {
    out.position = ray.at(hit.t);
    const Vec3 normal = unit_normal_or_facing(hit.normal, ray.direction);
    out.geometric_normal = normal;
    out.shading_normal = normal;
    out.object_size = max_abs_component(bounds.upper - bounds.lower);
}

// Which type runs the intersection of a shape S (S itself unless it names an Intersector).
template <typename S, typename = void>
struct ShapeTraits {
    using Intersector = S;
    static constexpr bool kSelfIntersecting = true;
};
template <typename S>
struct ShapeTraits<S, std::void_t<typename S::Intersector>> {
    using Intersector = typename S::Intersector;
    static constexpr bool kSelfIntersecting = false;
};

}  // namespace rayo
