#pragma once
// Ray/sphere intersection (seed 000 eqs. [3]-[9]) in two forms:
//  - SphereMath::Seed: the seed's algebraic form B = 2·Rd·(R0−Sc), C = |R0−Sc|² − Sr²,
//    D = B² − 4C, t = (−B ∓ √D)/2. Kept for comparison: it cancels catastrophically for small
//    spheres far from the origin of the ray.
//  - SphereMath::Stable (default, docs/architecture.md "Numerics"): Δ from the perpendicular
//  distance
//    r² − |f − (f·d)d|², roots via q = −(b + sign(b)√Δ), t = c/q and t = q, c = (|f|−r)(|f|+r).
//  - SphereMath::Double: the stable form evaluated in double precision, t rounded to float at
//    the end: the accuracy reference of the analytic-vs-BVH comparison.
// All apply the seed's rule: the near root if it lies past tnear, else the far root (the ray
// starts inside: seed 000 hits at t1 and flips the normal).
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "core/math.h"
#include "core/shapes/outline.h"
#include "core/shapes/shape.h"
#include "core/shapes/shape_fields.h"
#include "core/shapes/tessellation.h"

namespace rayo {

enum class SphereMath { Seed, Stable, Double };

// A sphere (seed 000 eq. [3]): a Shape (core/shapes/shape.h); the math of its nearest() is a
// template parameter so that each Embree callback runs one form without a per-ray switch.
struct Sphere {
    Vec3 center{0.0f};
    float radius = 1.0f;
    uint32_t material = 0;

    static constexpr const char* kName = "sphere";
    template <typename F>
    void fields(F& f) {
        f("center", center, FieldKind::Point);
        f("radius", radius, FieldKind::Positive);
    }
    std::optional<FieldProblem> problem() const { return std::nullopt; }
    Bounds3 bounds() const { return {center - Vec3(radius), center + Vec3(radius)}; }
    int crossings(const Vec3& origin, const Vec3& direction,
                  ShapeCrossing out[kMaxShapeCrossings]) const;
    template <SphereMath kMath = SphereMath::Stable>
    bool nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                 ShapeHit& hit) const;
    bool closed() const { return true; }
    void surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const;
    void parameterization(const Vec3& position, SurfaceHit& out) const;
    // The silhouette from out.view().eye: the circle where the cone of rays from the eye
    // touches the sphere (none when the eye is inside).
    void outline(Outline& out) const;
    // Its surface as parametric pieces for tessellation (core/shapes/tessellation.h).
    void pieces(SurfacePieces& out) const;
};

// uv and dpdu of a point at distance `radius` from `center`, in spherical coordinates about +y
// (the sphere's parameterization; CSG uses it about the centre of its bounds).
void spherical_parameterization(const Vec3& center, float radius, const Vec3& position,
                                SurfaceHit& out);
// The same about the centre of a box (shapes with no natural parameterization: CSG, blobs).
void bounds_parameterization(const Bounds3& bounds, const Vec3& position, SurfaceHit& out);

// The seed's rule for two roots t0 <= t1: the near root if it lies in (tnear, tfar), else the
// far root (the ray starts inside: seed 000 hits at t1 and flips the normal).
template <typename T>
bool nearest_root_in_window(T t0, T t1, T tnear, T tfar, T& t_out, bool& far_root) {
    if (t0 > tnear && t0 < tfar) {
        t_out = t0;
        far_root = false;
        return true;
    }
    if (t1 > tnear && t1 < tfar) {
        t_out = t1;
        far_root = true;
        return true;
    }
    return false;
}

// `direction` must be unit length. Returns true and fills `hit` for the nearest root in
// (tnear, tfar). Templated on the scalar so the double reference shares the code.
template <typename T>
bool intersect_sphere_seed(const glm::vec<3, T>& origin, const glm::vec<3, T>& direction,
                           const glm::vec<3, T>& center, T radius, T tnear, T tfar, T& t_out,
                           bool& far_root) {
    const glm::vec<3, T> f = origin - center;
    const T b = T(2) * glm::dot(direction, f);     // seed 000 eq. [6]
    const T c = glm::dot(f, f) - radius * radius;  // seed 000 eq. [6]
    const T discriminant = b * b - T(4) * c;       // seed 000 eq. [7]
    if (!(discriminant > T(0))) return false;      // D <= 0: miss (tangent counts as miss)
    const T root = std::sqrt(discriminant);
    return nearest_root_in_window((-b - root) / T(2), (-b + root) / T(2), tnear, tfar, t_out,
                                  far_root);
}

// Both roots t0 <= t1 of the stable form; false when the line misses (or only touches).
template <typename T>
bool sphere_roots_stable(const glm::vec<3, T>& origin, const glm::vec<3, T>& direction,
                         const glm::vec<3, T>& center, T radius, T& t0, T& t1) {
    const glm::vec<3, T> f = origin - center;
    const T b = glm::dot(f, direction);
    const glm::vec<3, T> perpendicular = f - b * direction;
    const T discriminant = radius * radius - glm::dot(perpendicular, perpendicular);
    if (!(discriminant > T(0))) return false;
    const T length_f = glm::length(f);
    const T c = (length_f - radius) * (length_f + radius);
    const T q = -(b + std::copysign(std::sqrt(discriminant), b));
    // Roots of t² + 2bt + c = 0 are q and c/q (Vieta); q != 0 because discriminant > 0.
    t0 = c / q;
    t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

template <typename T>
bool intersect_sphere_stable(const glm::vec<3, T>& origin, const glm::vec<3, T>& direction,
                             const glm::vec<3, T>& center, T radius, T tnear, T tfar, T& t_out,
                             bool& far_root) {
    T t0, t1;
    return sphere_roots_stable(origin, direction, center, radius, t0, t1) &&
           nearest_root_in_window(t0, t1, tnear, tfar, t_out, far_root);
}

template <typename T>
inline bool intersect_sphere(SphereMath math, const glm::vec<3, T>& origin,
                             const glm::vec<3, T>& direction, const glm::vec<3, T>& center,
                             T radius, T tnear, T tfar, T& t_out, bool& far_root) {
    switch (math) {
        case SphereMath::Seed:
            return intersect_sphere_seed(origin, direction, center, radius, tnear, tfar, t_out,
                                         far_root);
        case SphereMath::Double: {
            // Double evaluation; the window test is repeated in T so that a root that rounds
            // onto tnear or tfar is not reported outside the caller's window.
            double t = 0.0;
            const bool hit = intersect_sphere_stable(
                glm::dvec3(origin), glm::dvec3(direction), glm::dvec3(center),
                static_cast<double>(radius), static_cast<double>(tnear), static_cast<double>(tfar),
                t, far_root);
            if (!hit) return false;
            const T rounded = static_cast<T>(t);
            if (!(rounded > tnear && rounded < tfar)) return false;
            t_out = rounded;
            return true;
        }
        case SphereMath::Stable:
            break;
    }
    return intersect_sphere_stable(origin, direction, center, radius, tnear, tfar, t_out, far_root);
}

// Seed 000 eq. [9]: n = (P − Sc)/Sr, flipped for a far-root hit.
template <typename T>
glm::vec<3, T> sphere_normal(const glm::vec<3, T>& point, const glm::vec<3, T>& center, T radius,
                             bool far_root) {
    const glm::vec<3, T> n = (point - center) / radius;
    return far_root ? -n : n;
}

template <SphereMath kMath>
bool Sphere::nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                     ShapeHit& hit) const {
    bool far_root;
    if (!intersect_sphere(kMath, origin, direction, center, radius, tnear, tfar, hit.t, far_root)) {
        return false;
    }
    // Outward; the integrator tells inside from outside by its sign against the ray
    // (equivalent to seed 000's flip for far-root hits).
    hit.normal = origin + hit.t * direction - center;
    return true;
}

}  // namespace rayo
