#pragma once
// Constructive solid geometry by intervals along the ray (seed 004: "CSG by intervals along the
// ray: all hits sorted, boolean operations on the intervals, nearest endpoint"; Roth 1982, "Ray
// casting for modeling solids"). A Shape (core/shapes/shape.h): a binary tree whose leaves are
// closed primitive shapes (core/shapes/primitives.h) and whose inner nodes are union,
// intersection or difference, nested up to kMaxCsgDepth.
//
// Along the line o + t·d a solid is a sorted list of crossings that alternate entering and
// leaving (the inside intervals). A leaf's list is its crossings(); an operation merges its
// children's lists in t order, tracking whether the line is inside A and inside B, and keeps the
// crossings where the result (A∪B, A∩B or A∖B) changes between outside and inside. A crossing
// of B that bounds A∖B enters or leaves the other way round and its outward normal is B's
// flipped (the subtracted surface faces into B's hole). The nearest hit is the first crossing of
// the root's list past tnear; a ray starting inside finds its way out as any other crossing.
//
// The lists live on the stack: a tree may have at most kMaxCsgCrossings crossings along a line
// (each leaf counts its most, max_crossings(): kMaxShapeCrossings unless the shape says
// otherwise), a budget the scene reader checks, as it checks the depth.
#include <cstdint>
#include <optional>
#include <vector>

#include "core/shapes/outline.h"
#include "core/shapes/primitives.h"
#include "core/shapes/shape.h"
#include "core/shapes/tessellation.h"

namespace rayo {

enum class CsgOp : uint8_t { Union, Intersection, Difference };

constexpr int kMaxCsgDepth = 8;        // operations on a path from the root to a leaf
constexpr int kMaxCsgCrossings = 128;  // along one line, summed over the leaves' maxima

using CsgLeafShape = ShapeVariants<PrimitiveShapes>::Shape;
using CsgLeaf = ShapeVariants<PrimitiveShapes>::Intersector;

// The most crossings a leaf gives along one line: its max_crossings() when it has one.
template <typename S, typename = void>
struct HasMaxCrossings : std::false_type {};
template <typename S>
struct HasMaxCrossings<S, std::void_t<decltype(std::declval<const S&>().max_crossings())>>
    : std::true_type {};

struct CsgNode {
    int32_t leaf = -1;  // an index into Csg::leaves, or −1 for an operation
    CsgOp op = CsgOp::Union;
    int32_t left = -1, right = -1;  // indices into Csg::nodes (operations)
    int32_t budget = 0;             // the most crossings of this subtree along a line
    Bounds3 bounds;
};

struct Csg {
    std::vector<CsgLeafShape> leaf_shapes;  // as read (outline, parameterization)
    std::vector<CsgLeaf> leaves;            // their intersectors, index for index
    std::vector<CsgNode> nodes;             // children before parents; the root is last
    uint32_t material = 0;

    static constexpr const char* kName = "csg";

    // Building (the scene reader): each returns the new node's index.
    template <typename S>
    int add_leaf(const S& shape) {
        leaf_shapes.emplace_back(shape);
        leaves.push_back(ShapeVariants<PrimitiveShapes>::intersector_of(shape));
        CsgNode node;
        node.leaf = static_cast<int32_t>(leaves.size() - 1);
        if constexpr (HasMaxCrossings<S>::value) {
            node.budget = shape.max_crossings();
        } else {
            node.budget = kMaxShapeCrossings;
        }
        node.bounds = shape.bounds();
        nodes.push_back(node);
        return static_cast<int>(nodes.size() - 1);
    }
    int add_operation(CsgOp op, int left, int right);
    // The most crossings of all leaves along a line: at most kMaxCsgCrossings for a tree that
    // can be traced (the reader checks it).
    int leaf_budget() const {
        int sum = 0;
        for (const CsgNode& node : nodes) sum += node.leaf >= 0 ? node.budget : 0;
        return sum;
    }

    std::optional<FieldProblem> problem() const { return std::nullopt; }
    // The root's budget (the sum of its leaves') over kMaxCsgCrossings, or no tree at all.
    bool leaf_budget_exceeded() const {
        return nodes.empty() || nodes.back().budget > kMaxCsgCrossings;
    }
    bool closed() const { return true; }
    Bounds3 bounds() const { return nodes.empty() ? Bounds3{} : nodes.back().bounds; }
    // Writes at most kMaxShapeCrossings (the nearest ones) as the concept says; CSG itself
    // uses crossings_all.
    int crossings(const Vec3& origin, const Vec3& direction,
                  ShapeCrossing out[kMaxShapeCrossings]) const;
    // Every crossing of the line; `out` holds kMaxCsgCrossings.
    int crossings_all(const Vec3& origin, const Vec3& direction, ShapeCrossing* out) const;
    bool nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                 ShapeHit& hit) const;
    void surface(const Ray& ray, const ShapeHit& hit, SurfaceHit& out) const;
    // Spherical coordinates about the centre of the bounds (as the sphere's).
    void parameterization(const Vec3& position, SurfaceHit& out) const;
    // Every leaf's outline (subtracted parts included: the preview shows the construction).
    void outline(Outline& out) const;
    // None: a CSG is not tessellated for the radiosity solve (docs/radiosity.md, "Choices
    // and limits"); the solve warns and leaves it out (it still occludes).
    void pieces(SurfacePieces&) const {}

  private:
    int evaluate(int node, const Vec3& origin, const Vec3& direction, ShapeCrossing* out,
                 ShapeCrossing* scratch) const;
};

// Merges two sorted crossing lists by `op` into `out` (room for na + nb); returns the count.
int combine_crossings(CsgOp op, const ShapeCrossing* a, int na, const ShapeCrossing* b, int nb,
                      ShapeCrossing* out);

}  // namespace rayo
