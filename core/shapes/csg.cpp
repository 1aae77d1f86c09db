#include "core/shapes/csg.h"

#include <algorithm>
#include <cmath>

namespace rayo {
namespace {

Bounds3 merge(const Bounds3& a, const Bounds3& b) {
    return {glm::min(a.lower, b.lower), glm::max(a.upper, b.upper)};
}

// The overlap of two boxes; an empty overlap becomes a point (the solid is empty: no line
// crosses it, and Embree gets valid bounds).
Bounds3 overlap(const Bounds3& a, const Bounds3& b) {
    Bounds3 r{glm::max(a.lower, b.lower), glm::min(a.upper, b.upper)};
    if (!(r.lower.x <= r.upper.x && r.lower.y <= r.upper.y && r.lower.z <= r.upper.z)) {
        r.upper = r.lower;
    }
    return r;
}

bool inside(CsgOp op, bool in_a, bool in_b) {
    switch (op) {
        case CsgOp::Union:
            return in_a || in_b;
        case CsgOp::Intersection:
            return in_a && in_b;
        case CsgOp::Difference:
            break;
    }
    return in_a && !in_b;
}

}  // namespace

int combine_crossings(CsgOp op, const ShapeCrossing* a, int na, const ShapeCrossing* b, int nb,
                      ShapeCrossing* out) {
    // Seed 004's boolean on the intervals: walk both sorted lists in t order; the state of each
    // operand is the `entering` of its last crossing; keep the crossings where the result's
    // state changes (Roth 1982).
    bool in_a = false, in_b = false, in_result = false;
    int i = 0, j = 0, n = 0;
    while (i < na || j < nb) {
        const bool from_a = j >= nb || (i < na && a[i].t <= b[j].t);
        const ShapeCrossing& c = from_a ? a[i++] : b[j++];
        (from_a ? in_a : in_b) = c.entering;
        const bool now = inside(op, in_a, in_b);
        if (now == in_result) continue;
        in_result = now;
        // A subtracted surface bounds the result from the other side: its normal flips.
        const bool flip = !from_a && op == CsgOp::Difference;
        out[n++] = {c.t, now, flip ? -c.normal : c.normal};
    }
    return n;
}

int Csg::add_operation(CsgOp op, int left, int right) {
    CsgNode node;
    node.op = op;
    node.left = left;
    node.right = right;
    node.budget = nodes[left].budget + nodes[right].budget;
    const Bounds3 &a = nodes[left].bounds, &b = nodes[right].bounds;
    node.bounds = op == CsgOp::Union          ? merge(a, b)
                  : op == CsgOp::Intersection ? overlap(a, b)
                                              : a;  // A∖B lies within A
    nodes.push_back(node);
    return static_cast<int>(nodes.size() - 1);
}

int Csg::evaluate(int index, const Vec3& origin, const Vec3& direction, ShapeCrossing* out,
                  ShapeCrossing* scratch) const {
    // `out` has room for the node's budget; the children's lists go side by side into it, the
    // merge into `scratch` (needed only once both children are done) and back.
    const CsgNode& node = nodes[index];
    if (node.leaf >= 0) {
        return std::visit(
            [&](const auto& leaf) {
                // A leaf with its own maximum fills the room the budget gave it.
                if constexpr (HasMaxCrossings<std::decay_t<decltype(leaf)>>::value) {
                    return leaf.crossings(origin, direction, out, node.budget);
                } else {
                    return leaf.crossings(origin, direction, out);
                }
            },
            leaves[node.leaf]);
    }
    const int na = evaluate(node.left, origin, direction, out, scratch);
    if (na == 0 && node.op != CsgOp::Union) return 0;  // ∅∩B = ∅∖B = ∅
    const int nb = evaluate(node.right, origin, direction, out + na, scratch);
    if (nb == 0) return node.op == CsgOp::Intersection ? 0 : na;
    if (na == 0) return nb;  // a union with nothing: B's list is already at `out`
    const int n = combine_crossings(node.op, out, na, out + na, nb, scratch);
    std::copy(scratch, scratch + n, out);
    return n;
}

int Csg::crossings_all(const Vec3& origin, const Vec3& direction, ShapeCrossing* out) const {
    // A tree over the budget (the scene reader refuses one) would overflow the stack buffers.
    if (leaf_budget_exceeded()) return 0;
    ShapeCrossing scratch[kMaxCsgCrossings];
    return evaluate(static_cast<int>(nodes.size() - 1), origin, direction, out, scratch);
}

int Csg::crossings(const Vec3& origin, const Vec3& direction,
                   ShapeCrossing out[kMaxShapeCrossings]) const {
    ShapeCrossing all[kMaxCsgCrossings];
    const int n = std::min(crossings_all(origin, direction, all), kMaxShapeCrossings);
    std::copy(all, all + n, out);
    return n;
}

bool Csg::nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                  ShapeHit& hit) const {
    ShapeCrossing all[kMaxCsgCrossings];
    const int n = crossings_all(origin, direction, all);
    for (int i = 0; i < n; ++i) {
        if (all[i].t > tnear && all[i].t < tfar) {
            hit.t = all[i].t;
            hit.normal = all[i].normal;
            return true;
        }
        if (all[i].t >= tfar) break;
    }
    return false;
}

void Csg::surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const {
    surface_at_ray_point(ray, hit, bounds(), out);
}

void Csg::parameterization(const Vec3& position, SurfaceHit& out) const {
    bounds_parameterization(bounds(), position, out);
}

void Csg::outline(Outline& out) const {
    for (const CsgLeafShape& shape : leaf_shapes) {
        std::visit([&](const auto& s) { s.outline(out); }, shape);
    }
}

}  // namespace rayo
