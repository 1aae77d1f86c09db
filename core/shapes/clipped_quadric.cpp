#include "core/shapes/clipped_quadric.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rayo {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// An interval of the line and what bounds it at each end: the quadric (its gradient gives the
// normal) or a face of the clip box (`face` = outward local normal).
struct End {
    double t = 0.0;
    bool on_box = false;
    DVec3 face{0.0};
};
struct Interval {
    End start, end;
};

// The slab interval of the local box (Kay & Kajiya 1986, as core/shapes/box.cpp), in double.
bool box_interval(const DVec3& lower, const DVec3& upper, const DVec3& o, const DVec3& d,
                  End& enter, End& exit) {
    enter = {-kInfinity, true, DVec3(0.0)};
    exit = {kInfinity, true, DVec3(0.0)};
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0) {
            if (o[axis] < lower[axis] || o[axis] > upper[axis]) return false;
            continue;
        }
        double t0 = (lower[axis] - o[axis]) / d[axis], t1 = (upper[axis] - o[axis]) / d[axis];
        DVec3 n0(0.0), n1(0.0);
        n0[axis] = -1.0;
        n1[axis] = 1.0;
        if (t0 > t1) {
            std::swap(t0, t1);
            std::swap(n0, n1);
        }
        if (t0 > enter.t) enter = {t0, true, n0};
        if (t1 < exit.t) exit = {t1, true, n1};
    }
    return enter.t < exit.t && std::isfinite(enter.t) && std::isfinite(exit.t);
}

// The intervals of t where a·t² + b·t + c <= 0 (at most two, sorted). The roots by the stable
// form (docs/stability.md): r = −(b + sign(b)·√Δ)/2, roots r/a and c/r, so neither root comes
// from a difference of nearly equal numbers; a ≈ 0 (a ray along a paraboloid's or a cylinder's
// axis) leaves c/r accurate and sends r/a far away, where the box clips it.
int inside_intervals(double a, double b, double c, Interval out[2]) {
    const End minus{-kInfinity}, plus{kInfinity};
    if (a == 0.0) {
        if (b == 0.0) {
            if (!(c < 0.0)) return 0;
            out[0] = {minus, plus};
            return 1;
        }
        const End root{-c / b};
        out[0] = b > 0.0 ? Interval{minus, root} : Interval{root, plus};
        return 1;
    }
    const double discriminant = b * b - 4.0 * a * c;
    if (!(discriminant > 0.0)) {  // no crossing (a touching line counts as none, as the sphere)
        if (!(a < 0.0)) return 0;
        out[0] = {minus, plus};
        return 1;
    }
    const double r = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double t0 = r / a, t1 = c / r;
    if (t0 > t1) std::swap(t0, t1);
    if (a > 0.0) {
        out[0] = {End{t0}, End{t1}};
        return 1;
    }
    out[0] = {minus, End{t0}};
    out[1] = {End{t1}, plus};
    return 2;
}

}  // namespace

int ClippedQuadric::crossings(const Vec3& o, const Vec3& d,
                              ShapeCrossing out[kMaxShapeCrossings]) const {
    const DMat3 to_local_rotation = glm::transpose(rotation);
    const DVec3 lo = to_local_rotation * (DVec3(o) - origin);
    const DVec3 ld = to_local_rotation * DVec3(d);
    End box_enter, box_exit;
    if (!box_interval(lower, upper, lo, ld, box_enter, box_exit)) return 0;
    // Solve about the middle of the box interval, a point near the shape: q there is of the
    // shape's own size, not the difference of two large terms as it would be at a far origin.
    const double shift = 0.5 * (box_enter.t + box_exit.t);
    const DVec3 p = lo + shift * ld;
    const DVec3 mp = m * p;
    const double a = glm::dot(ld, m * ld);
    const double b = 2.0 * glm::dot(ld, mp) + glm::dot(g, ld);
    const double c = glm::dot(p, mp) + glm::dot(g, p) + j;
    Interval inside[2];
    const int count = inside_intervals(a, b, c, inside);
    const End box_start{box_enter.t - shift, true, box_enter.face};
    const End box_end{box_exit.t - shift, true, box_exit.face};

    int n = 0;
    const auto emit = [&](const End& end, bool entering) {
        if (!capped && end.on_box) return;
        DVec3 normal = end.face;
        if (!end.on_box) normal = 2.0 * (m * (p + end.t * ld)) + g;  // ∇q
        out[n] = {static_cast<float>(shift + end.t), entering, Vec3(rotation * normal)};
        ++n;
    };
    for (int k = 0; k < count; ++k) {
        const End start = inside[k].start.t > box_start.t ? inside[k].start : box_start;
        const End end = inside[k].end.t < box_end.t ? inside[k].end : box_end;
        if (!(start.t < end.t)) continue;
        emit(start, true);
        emit(end, false);
    }
    return n;
}

bool ClippedQuadric::nearest(const Vec3& o, const Vec3& d, float tnear, float tfar,
                             ShapeHit& hit) const {
    ShapeCrossing crossing[kMaxShapeCrossings];
    const int n = crossings(o, d, crossing);
    for (int i = 0; i < n; ++i) {
        if (crossing[i].t > tnear && crossing[i].t < tfar) {
            hit.t = crossing[i].t;
            hit.normal = crossing[i].normal;
            return true;
        }
    }
    return false;
}

Bounds3 ClippedQuadric::bounds() const {
    // The rotated box's extent along world axis i: Σ_k |R_ik|·half_k.
    const DVec3 centre = to_world(0.5 * (lower + upper)), half = 0.5 * (upper - lower);
    DVec3 extent(0.0);
    for (int k = 0; k < 3; ++k) extent += glm::abs(rotation[k]) * half[k];
    extent *= 1.0 + 1e-6;
    return {Vec3(centre - extent), Vec3(centre + extent)};
}

float ClippedQuadric::size() const {
    const DVec3 side = upper - lower;
    return static_cast<float>(std::max({side.x, side.y, side.z}));
}

void ClippedQuadric::surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const {
    out.position = ray.at(hit.t);
    // A zero gradient (a cone's apex, a point where the surface is singular) faces the ray.
    const Vec3 normal = unit_normal_or_facing(hit.normal, ray.direction);
    out.geometric_normal = normal;
    out.shading_normal = normal;
    out.object_size = size();
}

void ClippedQuadric::parameterization(const Vec3& position, SurfaceHit& out) const {
    // u = 1/2 + φ/2π about the local z axis, v = (z − lower.z)/(upper.z − lower.z);
    // ∂p/∂u = 2π·(−y, x, 0) (local).
    const DVec3 local = to_local(DVec3(position));
    const double phi = std::atan2(local.y, local.x);
    out.uv = glm::vec2(static_cast<float>(0.5 + phi / (2.0 * M_PI)),
                       static_cast<float>((local.z - lower.z) / (upper.z - lower.z)));
    out.dpdu = Vec3(rotation * (2.0 * M_PI * DVec3(-local.y, local.x, 0.0)));
}

void ClippedQuadric::add_box_edges(Outline& out) const {
    const auto corner = [&](int k) {
        return to_world(
            DVec3(k & 1 ? upper.x : lower.x, k & 2 ? upper.y : lower.y, k & 4 ? upper.z : lower.z));
    };
    for (int k = 0; k < 8; ++k) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (!(k & bit)) out.add_segment(corner(k), corner(k | bit));
        }
    }
}

}  // namespace rayo
