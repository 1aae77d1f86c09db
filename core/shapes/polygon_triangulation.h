#pragma once
// Triangulation of simple planar polygons, convex or concave. NFF polygons may be concave (the
// NFF specification: "only the first two edges are guaranteed to form a convex angle"; the SPD
// gears are 144-vertex concave outlines), so a fan around the first vertex is not enough.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace rayo {

using PolygonTriangle = std::array<uint32_t, 3>;

// The most vertices a polygon (an NFF `p`, a JSON polygon, a face of an OBJ, PLY or OFF mesh)
// may have: ear clipping, rayo's and the mesh libraries' alike, takes time quadratic in the
// count (one face of 10^5 vertices ran past 20 s, 3·10^4 took 6.1 s; docs/limits.md, "Input
// files"). Real polygons have a few hundred at most (the SPD gears 144).
constexpr size_t kMaxPolygonVertices = 4096;
// "a polygon may have at most 4096 vertices", for the loaders' messages.
std::string polygon_vertex_limit_text(size_t count);  // indices into the polygon's vertices

// Newell's normal of a polygon: twice its vector area, pointing to the side from which the
// vertices run counter-clockwise (right-handed). Zero for a polygon that encloses no area.
DVec3 newell_normal(const std::vector<Vec3>& vertices);

// Whether the polygon, projected onto the plane of its Newell normal, is convex: every turn is to
// the left or straight (within a relative 1e-6 for float input) and the outline goes around once.
bool is_convex_polygon(const std::vector<Vec3>& vertices);

// Triangles that cover a simple (not self-intersecting) planar polygon, each wound like the
// polygon (its normal along the Newell normal), N − 2 of them for N vertices. A convex polygon
// gives the fan (0, 1, 2), (0, 2, 3), ... (the triangles rayo always made for convex polygons);
// any other polygon is ear-clipped in the plane of its Newell normal. Collinear vertices give
// zero-area triangles, which callers drop. Empty when there are fewer than three vertices or the
// polygon encloses no area. A self-intersecting polygon still gets N − 2 triangles, but they
// need not cover it exactly.
std::vector<PolygonTriangle> triangulate_polygon(const std::vector<Vec3>& vertices);

}  // namespace rayo
