#include "core/shapes/cone.h"

#include <cmath>
#include <limits>

namespace rayo {

ConeFrame make_cone_frame(const Cone& cone) {
    ConeFrame f;
    f.base = DVec3(cone.base);
    const DVec3 axis_full = DVec3(cone.apex) - f.base;
    f.height = glm::length(axis_full);
    if (!(f.height > 0.0)) {
        f.height = 0.0;
        return f;
    }
    f.axis = axis_full / f.height;
    f.base_radius = cone.base_radius;
    f.slope = (double(cone.apex_radius) - f.base_radius) / f.height;
    return f;
}

void cone_bounds(const Cone& cone, Vec3& lower, Vec3& upper) {
    const Vec3 axis_full = cone.apex - cone.base;
    const float length = glm::length(axis_full);
    const Vec3 axis = length > 0.0f ? axis_full / length : Vec3(0.0f);
    // Half-extent of a unit circle around `axis`, per world axis (rounded up a little).
    const Vec3 extent = glm::sqrt(glm::max(Vec3(1.0f) - axis * axis, Vec3(0.0f))) * 1.0001f;
    lower = glm::min(cone.base - cone.base_radius * extent, cone.apex - cone.apex_radius * extent);
    upper = glm::max(cone.base + cone.base_radius * extent, cone.apex + cone.apex_radius * extent);
}

bool intersect_cone(const ConeFrame& cone, const Vec3& origin, const Vec3& direction, float tnear,
                    float tfar, float& t_out, Vec3& normal) {
    if (cone.height == 0.0) return false;
    const DVec3& base = cone.base;
    const DVec3& axis = cone.axis;
    const double height = cone.height;
    const double r0 = cone.base_radius;
    const double slope = cone.slope;

    const DVec3 d(direction), w = DVec3(origin) - base;
    const double w_axis = glm::dot(w, axis), d_axis = glm::dot(d, axis);
    const DVec3 w_perp = w - w_axis * axis, d_perp = d - d_axis * axis;
    // |w⊥ + t·d⊥|² = (R + K·t)², R = r0 + slope·(w·a), K = slope·(d·a)
    const double radius_at_origin = r0 + slope * w_axis, radius_rate = slope * d_axis;
    const double a = glm::dot(d_perp, d_perp) - radius_rate * radius_rate;
    const double b = 2.0 * (glm::dot(w_perp, d_perp) - radius_at_origin * radius_rate);
    const double c = glm::dot(w_perp, w_perp) - radius_at_origin * radius_at_origin;

    double roots[2];
    int count = 0;
    if (std::abs(a) < 1e-14) {
        if (std::abs(b) < 1e-300) return false;
        roots[count++] = -c / b;
    } else {
        const double discriminant = b * b - 4.0 * a * c;
        if (discriminant < 0.0) return false;
        const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
        double t0 = q / a, t1 = (q != 0.0) ? c / q : t0;
        if (t0 > t1) std::swap(t0, t1);
        roots[count++] = t0;
        roots[count++] = t1;
    }
    for (int i = 0; i < count; ++i) {
        const double t = roots[i];
        if (!(t > tnear && t < tfar)) continue;
        const double s = w_axis + t * d_axis;
        const double radius = r0 + slope * s;
        if (s < 0.0 || s > height || radius < 0.0) continue;  // outside the segment / other nappe
        const DVec3 radial = w_perp + t * d_perp;
        // Gradient of |p⊥|² − r(s)²: 2p⊥ − 2·r(s)·slope·a.
        const DVec3 gradient = radial - radius * slope * axis;
        const double length = glm::length(gradient);
        if (!(length > 0.0)) continue;
        t_out = static_cast<float>(t);
        normal = Vec3(gradient / length);
        return true;
    }
    return false;
}

ConeFrame Cone::intersector() const {
    return make_cone_frame(*this);
}

std::optional<FieldProblem> Cone::problem() const {
    if (!(glm::length(apex - base) > 0.0f)) {
        return FieldProblem{"apex", "expected apex to differ from base"};
    }
    if (!(base_radius > 0.0f || apex_radius > 0.0f)) {
        return FieldProblem{"base_radius", "expected base_radius or apex_radius > 0"};
    }
    return std::nullopt;
}

Bounds3 Cone::bounds() const {
    Bounds3 b;
    cone_bounds(*this, b.lower, b.upper);
    return b;
}

bool ConeFrame::nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                        ShapeHit& hit) const {
    return intersect_cone(*this, origin, direction, tnear, tfar, hit.t, hit.normal);
}

int ConeFrame::crossings(const Vec3& origin, const Vec3& direction,
                         ShapeCrossing out[kMaxShapeCrossings]) const {
    // Walk the hits along the line: each crossing found becomes the window's new start.
    int count = 0;
    float tnear = -std::numeric_limits<float>::max();
    float t;
    Vec3 normal;
    while (count < kMaxShapeCrossings &&
           intersect_cone(*this, origin, direction, tnear, std::numeric_limits<float>::max(), t,
                          normal)) {
        out[count++] = {t, glm::dot(direction, normal) < 0.0f, normal};
        tnear = t;
    }
    return count;
}

void Cone::surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const {
    out.position = ray.at(hit.t);
    out.geometric_normal = glm::normalize(hit.normal);
    out.shading_normal = out.geometric_normal;
    out.object_size = glm::max(glm::length(apex - base), glm::max(base_radius, apex_radius));
}

void Cone::parameterization(const Vec3& position, SurfaceHit& out) const {
    // u: the angle around the axis from a fixed perpendicular, v: the axial fraction base -> apex;
    // ∂p/∂u = 2π·r(v)·(the tangent of the circle).
    const Vec3 axis = glm::normalize(apex - base);
    const Vec3 helper = std::abs(axis.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 e1 = glm::normalize(glm::cross(axis, helper)), e2 = glm::cross(axis, e1);
    const Vec3 w = position - base;
    const float height = glm::length(apex - base);
    const float v = glm::dot(w, axis) / height;
    const float angle = std::atan2(glm::dot(w, e2), glm::dot(w, e1));
    const float radius = base_radius + v * (apex_radius - base_radius);
    out.uv = glm::vec2(0.5f + angle / (2.0f * kPi), v);
    out.dpdu = 2.0f * kPi * radius * (std::cos(angle) * e2 - std::sin(angle) * e1);
}

void Cone::outline(Outline& out) const {
    const ConeFrame f = make_cone_frame(*this);
    if (f.height == 0.0) return;
    const DVec3 apex_center = f.base + f.height * f.axis;
    out.add_circle(f.base, f.axis, f.base_radius);
    out.add_circle(apex_center, f.axis, apex_radius);
    // The generator at angle φ, P(s) = B + s·a + r(s)·e(φ) with e(φ) = cos φ·u + sin φ·v, has
    // the normal e(φ) − slope·a all along it, and (P(s) − E)·(e − slope·a) does not depend on
    // s: it is e·w + r0 − slope·(a·w), w = B − E. The silhouette generators make it zero:
    // A cos φ + B sin φ = C with A = u·w, B = v·w, C = slope·(a·w) − r0.
    DVec3 u, v;
    perpendicular_frame(f.axis, u, v);
    const DVec3 w = f.base - out.view().eye;
    const double a = glm::dot(u, w), b = glm::dot(v, w);
    const double c = f.slope * glm::dot(f.axis, w) - f.base_radius;
    const double rho = std::hypot(a, b);
    if (!(rho > std::abs(c))) return;  // the eye sees the surface from inside its extension
    const double phi0 = std::atan2(b, a), delta = std::acos(c / rho);
    for (const double phi : {phi0 - delta, phi0 + delta}) {
        const DVec3 e = std::cos(phi) * u + std::sin(phi) * v;
        out.add_segment(f.base + f.base_radius * e, apex_center + double(apex_radius) * e);
    }
}

void Cone::pieces(SurfacePieces& out) const {
    // The open side: ρ(z) = r0 + k·z along the axis, so ρ² = r0² + 2·r0·k·z + k²·z².
    const ConeFrame f = make_cone_frame(*this);
    if (!(f.height > 0.0)) return;
    SurfacePiece piece;
    piece.kind = SurfacePiece::Kind::Revolution;
    piece.origin = f.base;
    DVec3 u, v;
    perpendicular_frame(f.axis, u, v);
    piece.frame = glm::dmat3(u, v, f.axis);
    piece.z0 = 0.0;
    piece.z1 = f.height;
    piece.r2 = {f.base_radius * f.base_radius, 2.0 * f.base_radius * f.slope, f.slope * f.slope};
    out.push_back(piece);
}

}  // namespace rayo
