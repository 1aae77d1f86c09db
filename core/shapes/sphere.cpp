#include "core/shapes/sphere.h"

#include <cmath>

namespace rayo {

int Sphere::crossings(const Vec3& origin, const Vec3& direction,
                      ShapeCrossing out[kMaxShapeCrossings]) const {
    float t0, t1;
    if (!sphere_roots_stable(origin, direction, center, radius, t0, t1)) return 0;
    out[0] = {t0, true, origin + t0 * direction - center};
    out[1] = {t1, false, origin + t1 * direction - center};
    return 2;
}

void Sphere::surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const {
    // Re-project the hit point onto the sphere (DESIGN "Numerics", docs/architecture.md). A
    // sphere below one ulp of its position can put the hit on its centre in float: face the ray
    // instead of dividing by zero (a NaN origin would reach Embree; docs/stability.md).
    const Vec3 offset = ray.at(hit.t) - center;
    const float length_squared = glm::dot(offset, offset);
    const Vec3 outward =
        length_squared > 0.0f ? offset * glm::inversesqrt(length_squared) : -ray.direction;
    out.position = center + radius * outward;
    out.geometric_normal = outward;
    out.shading_normal = outward;
    out.object_size = radius;
}

void Sphere::parameterization(const Vec3& position, SurfaceHit& out) const {
    spherical_parameterization(center, radius, position, out);
}

void spherical_parameterization(const Vec3& center, float radius, const Vec3& position,
                                SurfaceHit& out) {
    // Spherical coordinates about +y: n = (sinθ·sinφ, cosθ, sinθ·cosφ), u = 1/2 + φ/2π, v = θ/π;
    // ∂p/∂u = 2π·r·(n.z, 0, −n.x).
    const Vec3 n = (position - center) / radius;
    const float phi = std::atan2(n.x, n.z);
    const float theta = std::acos(glm::clamp(n.y, -1.0f, 1.0f));
    out.uv = glm::vec2(0.5f + phi / (2.0f * kPi), theta / kPi);
    out.dpdu = 2.0f * kPi * radius * Vec3(n.z, 0.0f, -n.x);
}

void Sphere::pieces(SurfacePieces& out) const {
    SurfacePiece piece;
    piece.kind = SurfacePiece::Kind::Sphere;
    piece.origin = DVec3(center);
    piece.frame = glm::dmat3(static_cast<double>(radius));
    out.push_back(piece);
}

void bounds_parameterization(const Bounds3& bounds, const Vec3& position, SurfaceHit& out) {
    const Vec3 centre = 0.5f * (bounds.lower + bounds.upper);
    const float radius = glm::length(position - centre);
    if (radius > 0.0f) {
        spherical_parameterization(centre, radius, position, out);
    } else {
        out.uv = glm::vec2(0.0f);
        out.dpdu = Vec3(0.0f);
    }
}

void Sphere::outline(Outline& out) const {
    // The rays from the eye E that touch the sphere form a cone; they touch it on the circle
    // about C − (r²/d²)(C − E) of radius r·√(d² − r²)/d, in the plane normal to C − E
    // (d = |C − E|): the tangent rays are perpendicular to the radius at the touching point.
    const DVec3 c(center), to_center = c - out.view().eye;
    const double r = radius, d2 = glm::dot(to_center, to_center);
    if (!(d2 > r * r)) return;  // the eye inside or on the sphere: no silhouette
    const double d = std::sqrt(d2);
    out.add_circle(c - (r * r / d2) * to_center, to_center / d, r * std::sqrt(d2 - r * r) / d);
}

}  // namespace rayo
