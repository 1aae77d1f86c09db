#pragma once
// The intersector shared by every quadric shape (core/shapes/quadric.h and the named forms in
// core/shapes/quadric_forms.h): the solid {q(x) <= 0} of an implicit quadric
//   q(x) = xᵀ·M·x + g·x + j
// clipped to an axis-aligned box, both given in a local frame (an orthonormal rotation and an
// origin). Seed 004 §4.2.3.1: the sphere's discriminant method "applies in a very similar way to
// the other quadrics (paraboloids, ellipsoids, hyperboloids)"; the roots here use the stable form
// of the sphere (docs/stability.md): q = −(b + sign(b)·√Δ)/2, roots q/a and c/q.
//
// Along a line the inside of the quadric is at most two intervals (a > 0: between the roots;
// a < 0: outside them; a = 0: a half-line) and the box is one interval; the solid is their
// intersection, so a line crosses it at most four times. A `capped` solid is closed: where an
// interval ends on the box, the crossing is on the box face (a cylinder's caps are the discs the
// faces cut from it). An open one (`capped` false) keeps only the quadric's own crossings.
#include <glm/mat3x3.hpp>

#include "core/math.h"
#include "core/shapes/outline.h"
#include "core/shapes/shape.h"
#include "core/shapes/tessellation.h"

namespace rayo {

using DMat3 = glm::dmat3;

struct ClippedQuadric {
    // Local coordinates of a world point p: rotationᵀ·(p − origin). The columns of `rotation`
    // are the local axes in world space (orthonormal).
    DVec3 origin{0.0};
    DMat3 rotation{1.0};
    DMat3 m{0.0};  // symmetric
    DVec3 g{0.0};
    double j = 0.0;
    DVec3 lower{-1.0}, upper{1.0};  // the local clip box
    bool capped = true;

    // Every crossing of the line o + t·d (unit d, world space), sorted by t, with the outward
    // normals (world space, any length).
    int crossings(const Vec3& o, const Vec3& d, ShapeCrossing out[kMaxShapeCrossings]) const;
    // A solid unless `capped` is false (CSG children must be solids).
    bool closed() const { return capped; }
    // The first crossing with t in (tnear, tfar), tested after rounding t to float.
    bool nearest(const Vec3& o, const Vec3& d, float tnear, float tfar, ShapeHit& hit) const;

    // World-space axis-aligned bounds of the clip box.
    Bounds3 bounds() const;
    // The clip box's largest side: the shape's size for spawned-ray offsets.
    float size() const;
    // q at a world point (0 on the surface, < 0 inside).
    double value(const DVec3& world) const {
        const DVec3 x = to_local(world);
        return glm::dot(x, m * x) + glm::dot(g, x) + j;
    }
    DVec3 to_local(const DVec3& world) const { return glm::transpose(rotation) * (world - origin); }
    DVec3 to_world(const DVec3& local) const { return origin + rotation * local; }
    // Cylindrical coordinates about the local z axis: u = angle/2π, v = z across the box.
    void parameterization(const Vec3& position, SurfaceHit& out) const;
    // Position and unit normals of a hit; the normal is the one nearest() reported.
    void surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const;
    // A closed polyline of `chords` segments through local points f(s), s in [0, 1).
    template <typename F>
    void add_local_loop(Outline& out, int chords, F f) const {
        DVec3 previous = to_world(f(0.0));
        for (int i = 1; i <= chords; ++i) {
            const DVec3 next = to_world(f(static_cast<double>(i % chords) / chords));
            out.add_segment(previous, next);
            previous = next;
        }
    }
    // An open polyline of `chords` segments through local points f(s), s in [0, 1].
    template <typename F>
    void add_local_curve(Outline& out, int chords, F f) const {
        DVec3 previous = to_world(f(0.0));
        for (int i = 1; i <= chords; ++i) {
            const DVec3 next = to_world(f(static_cast<double>(i) / chords));
            out.add_segment(previous, next);
            previous = next;
        }
    }
    // The twelve edges of the clip box.
    void add_box_edges(Outline& out) const;
};

// A Shape's members implemented through its intersector (S::intersector() returns a
// ClippedQuadric): every quadric shape derives from QuadricShape<itself>.
template <typename S>
struct QuadricShape {
    using Intersector = ClippedQuadric;
    Bounds3 bounds() const { return self().intersector().bounds(); }
    int crossings(const Vec3& origin, const Vec3& direction,
                  ShapeCrossing out[kMaxShapeCrossings]) const {
        return self().intersector().crossings(origin, direction, out);
    }
    bool nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                 ShapeHit& hit) const {
        return self().intersector().nearest(origin, direction, tnear, tfar, hit);
    }
    bool closed() const { return self().intersector().closed(); }
    void surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const {
        self().intersector().surface(ray, hit, out);
    }
    void parameterization(const Vec3& position, SurfaceHit& out) const {
        self().intersector().parameterization(position, out);
    }

  private:
    const S& self() const { return static_cast<const S&>(*this); }
};

}  // namespace rayo
