#include "core/shapes/quadric_forms.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rayo {
namespace {

constexpr int kOutlineChords = 64;
constexpr double kMargin = 1.001;  // the radial clip lies beyond the surface: it cuts nothing

// A ClippedQuadric in the frame at `origin` whose local z is `axis`.
ClippedQuadric framed(const Vec3& origin, const Vec3& axis) {
    ClippedQuadric q;
    q.origin = DVec3(origin);
    const DVec3 w = glm::normalize(DVec3(axis));
    DVec3 u, v;
    perpendicular_frame(w, u, v);
    q.rotation = DMat3(u, v, w);
    return q;
}

DVec3 on_circle(double radius, double s, double z) {
    const double angle = 2.0 * M_PI * s;
    return DVec3(radius * std::cos(angle), radius * std::sin(angle), z);
}

// A profile curve of a surface of revolution at angle k·π/2: radius_of(z) over [z0, z1].
template <typename R>
void add_profiles(const ClippedQuadric& q, Outline& out, double z0, double z1, R radius_of) {
    for (int k = 0; k < 4; ++k) {
        const DVec3 direction = on_circle(1.0, 0.25 * k, 0.0);
        q.add_local_curve(out, kOutlineChords, [&](double s) {
            const double z = z0 + s * (z1 - z0);
            return radius_of(z) * direction + DVec3(0.0, 0.0, z);
        });
    }
}

// A piece of `kind` placed in the quadric's local frame.
SurfacePiece in_frame_of(const ClippedQuadric& q, SurfacePiece::Kind kind) {
    SurfacePiece piece;
    piece.kind = kind;
    piece.origin = q.origin;
    piece.frame = q.rotation;
    return piece;
}

// A surface of revolution about the local z axis of a quadric's frame, over [z0, z1].
SurfacePiece revolution(const ClippedQuadric& q, double z0, double z1,
                        const std::array<double, 3>& r2) {
    SurfacePiece piece = in_frame_of(q, SurfacePiece::Kind::Revolution);
    piece.z0 = z0;
    piece.z1 = z1;
    piece.r2 = r2;
    return piece;
}

// The disc of `radius` at local height z that a box face cuts from a capped solid; `down` when
// its outward normal is −z.
SurfacePiece cap(const ClippedQuadric& q, double z, double radius, bool down) {
    SurfacePiece piece = in_frame_of(q, SurfacePiece::Kind::Cap);
    piece.z0 = z;
    piece.radius = radius;
    piece.flip = down;
    return piece;
}

}  // namespace

std::optional<FieldProblem> Ellipsoid::problem() const {
    if (!(radii.x > 0.0f && radii.y > 0.0f && radii.z > 0.0f)) {
        return FieldProblem{"radii", "expected three numbers > 0"};
    }
    return std::nullopt;
}

ClippedQuadric Ellipsoid::intersector() const {
    ClippedQuadric q;
    q.origin = DVec3(center);
    const DVec3 r(radii);
    q.m = DMat3(1.0 / (r.x * r.x), 0.0, 0.0, 0.0, 1.0 / (r.y * r.y), 0.0, 0.0, 0.0,
                1.0 / (r.z * r.z));
    q.j = -1.0;
    q.upper = kMargin * r;
    q.lower = -q.upper;
    return q;
}

void Ellipsoid::outline(Outline& out) const {
    const ClippedQuadric q = intersector();
    const DVec3 r(radii);
    for (int axis = 0; axis < 3; ++axis) {
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        q.add_local_loop(out, kOutlineChords, [&](double s) {
            DVec3 p(0.0);
            p[a] = r[a] * std::cos(2.0 * M_PI * s);
            p[b] = r[b] * std::sin(2.0 * M_PI * s);
            return p;
        });
    }
}

std::optional<FieldProblem> Cylinder::problem() const {
    if (!(glm::length(DVec3(top) - DVec3(base)) > 0.0)) {
        return FieldProblem{"top", "expected top != base"};
    }
    return std::nullopt;
}

ClippedQuadric Cylinder::intersector() const {
    ClippedQuadric q = framed(base, top - base);
    const double r = radius, h = glm::length(DVec3(top) - DVec3(base));
    q.m = DMat3(1.0 / (r * r), 0.0, 0.0, 0.0, 1.0 / (r * r), 0.0, 0.0, 0.0, 0.0);
    q.j = -1.0;
    q.lower = DVec3(-kMargin * r, -kMargin * r, 0.0);
    q.upper = DVec3(kMargin * r, kMargin * r, h);
    q.capped = capped;
    return q;
}

void Cylinder::outline(Outline& out) const {
    const ClippedQuadric q = intersector();
    const double h = q.upper.z;
    out.add_circle(DVec3(base), q.rotation[2], radius);
    out.add_circle(DVec3(top), q.rotation[2], radius);
    add_profiles(q, out, 0.0, h, [&](double) { return double(radius); });
}

ClippedQuadric Paraboloid::intersector() const {
    ClippedQuadric q = framed(vertex, axis);
    const double r = radius, h = height;
    q.m = DMat3(1.0 / (r * r), 0.0, 0.0, 0.0, 1.0 / (r * r), 0.0, 0.0, 0.0, 0.0);
    q.g = DVec3(0.0, 0.0, -1.0 / h);
    // Below the vertex by a margin too, so that the face z = 0 never meets the surface.
    q.lower = DVec3(-kMargin * r, -kMargin * r, (1.0 - kMargin) * h);
    q.upper = DVec3(kMargin * r, kMargin * r, h);
    q.capped = capped;
    return q;
}

void Paraboloid::outline(Outline& out) const {
    const ClippedQuadric q = intersector();
    out.add_circle(q.to_world(DVec3(0.0, 0.0, height)), q.rotation[2], radius);
    add_profiles(q, out, 0.0, height, [&](double z) { return radius * std::sqrt(z / height); });
}

std::optional<FieldProblem> Hyperboloid::problem() const {
    if (sheets != 1 && sheets != 2) return FieldProblem{"sheets", "expected 1 or 2"};
    if (sheets == 2 && !(0.5 * height > semi_axis)) {
        return FieldProblem{"height",
                            "expected height > 2 * semi_axis for two sheets (their vertices are "
                            "at ±semi_axis)"};
    }
    return std::nullopt;
}

double Hyperboloid::radius_at(double z) const {
    // ρ²/a² = (z/c)² ± 1: + one sheet, − two sheets.
    const double zc = z / semi_axis;
    return radius * std::sqrt(std::max(0.0, zc * zc + (sheets == 1 ? 1.0 : -1.0)));
}

ClippedQuadric Hyperboloid::intersector() const {
    ClippedQuadric q = framed(center, axis);
    const double a = radius, c = semi_axis, end = kMargin * radius_at(0.5 * height);
    q.m = DMat3(1.0 / (a * a), 0.0, 0.0, 0.0, 1.0 / (a * a), 0.0, 0.0, 0.0, -1.0 / (c * c));
    q.j = sheets == 1 ? -1.0 : 1.0;
    q.lower = DVec3(-end, -end, -0.5 * height);
    q.upper = DVec3(end, end, 0.5 * height);
    q.capped = capped;
    return q;
}

void Hyperboloid::outline(Outline& out) const {
    const ClippedQuadric q = intersector();
    const double half = 0.5 * height, end = radius_at(half);
    out.add_circle(q.to_world(DVec3(0.0, 0.0, half)), q.rotation[2], end);
    out.add_circle(q.to_world(DVec3(0.0, 0.0, -half)), q.rotation[2], end);
    const auto profile = [&](double z) { return radius_at(z); };
    if (sheets == 1) {
        out.add_circle(DVec3(center), q.rotation[2], radius);
        add_profiles(q, out, -half, half, profile);
    } else {
        add_profiles(q, out, semi_axis, half, profile);
        add_profiles(q, out, -half, -double(semi_axis), profile);
    }
}

void Ellipsoid::pieces(SurfacePieces& out) const {
    SurfacePiece piece;
    piece.kind = SurfacePiece::Kind::Sphere;
    piece.origin = DVec3(center);
    piece.frame = glm::dmat3(radii.x, 0.0, 0.0, 0.0, radii.y, 0.0, 0.0, 0.0, radii.z);
    out.push_back(piece);
}

void Cylinder::pieces(SurfacePieces& out) const {
    const ClippedQuadric q = intersector();
    const double r = radius;
    out.push_back(revolution(q, 0.0, q.upper.z, {r * r, 0.0, 0.0}));
    if (capped) {
        out.push_back(cap(q, 0.0, r, true));
        out.push_back(cap(q, q.upper.z, r, false));
    }
}

void Paraboloid::pieces(SurfacePieces& out) const {
    const ClippedQuadric q = intersector();
    const double r = radius, h = height;
    out.push_back(revolution(q, 0.0, h, {0.0, r * r / h, 0.0}));
    if (capped) out.push_back(cap(q, h, r, false));
}

void Hyperboloid::pieces(SurfacePieces& out) const {
    const ClippedQuadric q = intersector();
    const double a = radius, c = semi_axis, half = 0.5 * height;
    // ρ² = a²·((z/c)² ± 1): + one sheet, − two sheets.
    const std::array<double, 3> r2 = {sheets == 1 ? a * a : -a * a, 0.0, a * a / (c * c)};
    if (sheets == 1) {
        out.push_back(revolution(q, -half, half, r2));
    } else {
        out.push_back(revolution(q, c, half, r2));
        out.push_back(revolution(q, -half, -c, r2));
    }
    if (capped) {
        out.push_back(cap(q, -half, radius_at(-half), true));
        out.push_back(cap(q, half, radius_at(half), false));
    }
}

}  // namespace rayo
