#include "core/shapes/disk.h"

#include <cmath>

namespace rayo {
namespace {

// Two unit vectors completing `n` to a right-handed frame (e1 × e2 = n).
void tangent_frame(const Vec3& n, Vec3& e1, Vec3& e2) {
    const Vec3 helper = std::abs(n.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    e1 = glm::normalize(glm::cross(helper, n));
    e2 = glm::cross(n, e1);
}

}  // namespace

Bounds3 Disk::bounds() const {
    // Each world axis i: the disk extends r·√(1 − n_i²) (the cone's end-circle rule).
    const Vec3 extent =
        radius * glm::sqrt(glm::max(Vec3(1.0f) - normal * normal, Vec3(0.0f))) * 1.0001f;
    return {center - extent, center + extent};
}

int Disk::crossings(const Vec3& origin, const Vec3& direction,
                    ShapeCrossing out[kMaxShapeCrossings]) const {
    // The plane n·(p − c) = 0 at t = n·(c − o)/(n·d); inside when |p − c| <= r.
    const float denominator = glm::dot(normal, direction);
    if (denominator == 0.0f) return 0;
    const float t = glm::dot(normal, center - origin) / denominator;
    const Vec3 offset = origin + t * direction - center;
    if (!(glm::dot(offset, offset) <= radius * radius)) return 0;
    out[0] = {t, denominator < 0.0f, normal};
    return 1;
}

bool Disk::nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                   ShapeHit& hit) const {
    ShapeCrossing crossing[kMaxShapeCrossings];
    if (crossings(origin, direction, crossing) == 0) return false;
    if (!(crossing[0].t > tnear && crossing[0].t < tfar)) return false;
    hit.t = crossing[0].t;
    hit.normal = normal;
    return true;
}

void Disk::surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const {
    // Projected onto the plane, so the spawned-ray offset starts from the surface itself.
    const Vec3 p = ray.at(hit.t);
    out.position = p - glm::dot(p - center, normal) * normal;
    out.geometric_normal = normal;
    out.shading_normal = normal;
    out.object_size = radius;
}

void Disk::parameterization(const Vec3& position, SurfaceHit& out) const {
    // Polar: u = angle/2π from e1 toward e2, v = ρ/r; ∂p/∂u = 2π·ρ·(the circle's tangent).
    Vec3 e1, e2;
    tangent_frame(normal, e1, e2);
    const Vec3 w = position - center;
    const float x = glm::dot(w, e1), y = glm::dot(w, e2);
    const float angle = std::atan2(y, x);
    const float rho = std::sqrt(x * x + y * y);
    out.uv = glm::vec2(0.5f + angle / (2.0f * kPi), rho / radius);
    out.dpdu = 2.0f * kPi * (x * e2 - y * e1);
}

void Disk::outline(Outline& out) const {
    out.add_circle(DVec3(center), glm::normalize(DVec3(normal)), radius);
}

void Disk::pieces(SurfacePieces& out) const {
    SurfacePiece piece;
    piece.kind = SurfacePiece::Kind::Cap;
    piece.origin = DVec3(center);
    DVec3 u, v;
    const DVec3 w = glm::normalize(DVec3(normal));
    perpendicular_frame(w, u, v);
    piece.frame = glm::dmat3(u, v, w);
    piece.z0 = 0.0;
    piece.radius = radius;
    out.push_back(piece);
}

}  // namespace rayo
