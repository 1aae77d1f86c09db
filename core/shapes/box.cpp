#include "core/shapes/box.h"

#include <cmath>
#include <limits>

namespace rayo {

std::optional<FieldProblem> Box::problem() const {
    if (!(min.x < max.x && min.y < max.y && min.z < max.z)) {
        return FieldProblem{"max", "expected max > min on every axis"};
    }
    return std::nullopt;
}

bool Box::slabs(const Vec3& origin, const Vec3& direction, float& t_enter, Vec3& n_enter,
                float& t_exit, Vec3& n_exit) const {
    t_enter = -std::numeric_limits<float>::infinity();
    t_exit = std::numeric_limits<float>::infinity();
    n_enter = n_exit = Vec3(0.0f);
    for (int axis = 0; axis < 3; ++axis) {
        const float o = origin[axis], d = direction[axis];
        if (d == 0.0f) {
            if (o < min[axis] || o > max[axis]) return false;  // parallel, outside the slab
            continue;
        }
        const float inverse = 1.0f / d;
        float t0 = (min[axis] - o) * inverse, t1 = (max[axis] - o) * inverse;
        // The face at min has outward normal −e_axis, at max +e_axis.
        Vec3 n0(0.0f), n1(0.0f);
        n0[axis] = -1.0f;
        n1[axis] = 1.0f;
        if (t0 > t1) {
            std::swap(t0, t1);
            std::swap(n0, n1);
        }
        if (t0 > t_enter) {
            t_enter = t0;
            n_enter = n0;
        }
        if (t1 < t_exit) {
            t_exit = t1;
            n_exit = n1;
        }
    }
    return t_enter <= t_exit && std::isfinite(t_enter) && std::isfinite(t_exit);
}

int Box::crossings(const Vec3& origin, const Vec3& direction,
                   ShapeCrossing out[kMaxShapeCrossings]) const {
    float t_enter, t_exit;
    Vec3 n_enter, n_exit;
    if (!slabs(origin, direction, t_enter, n_enter, t_exit, n_exit)) return 0;
    out[0] = {t_enter, true, n_enter};
    out[1] = {t_exit, false, n_exit};
    return 2;
}

bool Box::nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                  ShapeHit& hit) const {
    float t_enter, t_exit;
    Vec3 n_enter, n_exit;
    if (!slabs(origin, direction, t_enter, n_enter, t_exit, n_exit)) return false;
    if (t_enter > tnear && t_enter < tfar) {
        hit = {t_enter, n_enter};
        return true;
    }
    if (t_exit > tnear && t_exit < tfar) {  // the ray starts inside
        hit = {t_exit, n_exit};
        return true;
    }
    return false;
}

void Box::surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const {
    // Snap the coordinate of the face's axis onto the face, so that the hit lies on the box.
    out.position = ray.at(hit.t);
    for (int axis = 0; axis < 3; ++axis) {
        if (hit.normal[axis] < 0.0f) out.position[axis] = min[axis];
        if (hit.normal[axis] > 0.0f) out.position[axis] = max[axis];
    }
    out.geometric_normal = hit.normal;
    out.shading_normal = hit.normal;
    out.object_size = max_abs_component(max - min);
}

void Box::parameterization(const Vec3& position, SurfaceHit& out) const {
    // Per face: (u, v) in [0, 1]² along the next two axes (cyclically) after the face's axis.
    const Vec3 size = max - min;
    const Vec3 local = (position - min) / size;
    const Vec3 to_min = glm::abs(position - min), to_max = glm::abs(position - max);
    int face_axis = 0;
    float best = std::numeric_limits<float>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        const float d = glm::min(to_min[axis], to_max[axis]) / size[axis];
        if (d < best) {
            best = d;
            face_axis = axis;
        }
    }
    const int u_axis = (face_axis + 1) % 3, v_axis = (face_axis + 2) % 3;
    out.uv = glm::vec2(local[u_axis], local[v_axis]);
    out.dpdu = Vec3(0.0f);
    out.dpdu[u_axis] = size[u_axis];
}

void Box::outline(Outline& out) const {
    // Corner k has max on axis i when bit i of k is set; an edge joins corners one bit apart.
    const auto corner = [&](int k) {
        return DVec3(k & 1 ? max.x : min.x, k & 2 ? max.y : min.y, k & 4 ? max.z : min.z);
    };
    for (int k = 0; k < 8; ++k) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (!(k & bit)) out.add_segment(corner(k), corner(k | bit));
        }
    }
}

void Box::pieces(SurfacePieces& out) const {
    // Six faces: for axis a, the face at min (outward −a) and at max (outward +a), spanned by
    // the box's extents along the two other axes.
    const DVec3 lo(min), hi(max);
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (int side = 0; side < 2; ++side) {
            SurfacePiece piece;
            piece.kind = SurfacePiece::Kind::Quad;
            piece.origin = lo;
            piece.origin[a] = side ? hi[a] : lo[a];
            DVec3 e1(0.0), e2(0.0), n(0.0);
            e1[b] = hi[b] - lo[b];
            e2[c] = hi[c] - lo[c];
            n[a] = side ? 1.0 : -1.0;
            piece.frame = glm::dmat3(e1, e2, n);
            out.push_back(piece);
        }
    }
}

}  // namespace rayo
