#pragma once
// Analytic shapes as triangles: each shape describes its surface as a few parametric pieces
// (`void pieces(SurfacePieces& out) const`, core/shapes/shape.h), and tessellate() cuts every
// piece into a regular grid in its own (s, t) ∈ [0, 1]², two triangles per cell. locate() is the
// inverse: the piece and (s, t) of a point on the surface, so that a hit found analytically can
// find its grid cell and interpolate values stored at the grid's vertices (the radiosity display,
// docs/radiosity.md). Every piece is one of four kinds, in a local frame `origin + frame·x`
// (frame: its columns are the local axes in world space, scaled for the ellipsoid):
//
//   Revolution  x = (ρ(z)·cos 2πs, ρ(z)·sin 2πs, z), z = z0 + t·(z1 − z0),
//               ρ(z)² = r2[0] + r2[1]·z + r2[2]·z²   (cylinders, cones, paraboloids, hyperboloids)
//   Sphere      x = (sin πt·cos 2πs, sin πt·sin 2πs, −cos πt)         (spheres, ellipsoids)
//   Cap         x = (t·radius·cos 2πs, t·radius·sin 2πs, z0)          (disks, the caps of solids)
//   Quad        x = (s, t, 0)                                          (the faces of boxes)
//
// The triangles face the outward normal of the surface (the winding is chosen against the
// analytic normal), so they are the one-sided patches of the radiosity solve.
#include <array>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <vector>

#include "core/math.h"

namespace rayo {

struct SurfacePiece {
    enum class Kind { Revolution, Sphere, Cap, Quad };
    Kind kind = Kind::Quad;
    DVec3 origin{0.0};
    glm::dmat3 frame{1.0};
    double z0 = 0.0, z1 = 1.0;   // Revolution: the axial range; Cap: its height
    std::array<double, 3> r2{};  // Revolution: ρ² as a polynomial in z
    double radius = 1.0;         // Cap
    // The surface's outward normal is the local one (below) or its opposite.
    bool flip = false;

    DVec3 point(double s, double t) const;
    // Unit, outward (zero where the surface has no normal: a cone's apex).
    DVec3 normal(double s, double t) const;
};
using SurfacePieces = std::vector<SurfacePiece>;

// A piece's grid: nu cells along s, nv along t.
struct PieceGrid {
    uint32_t nu = 1, nv = 1;
    uint32_t first_vertex = 0;    // (nu + 1)·(nv + 1) grid points from here, row-major in t
    uint32_t first_triangle = 0;  // 2 slots per cell from here (see TessellatedMesh::slot)
};

struct TessellatedMesh {
    std::vector<Vec3> positions;  // every grid point (coinciding points are not merged)
    std::vector<Vec3> normals;    // the analytic unit normal there
    std::vector<std::array<uint32_t, 3>> triangles;
    // Per triangle, how far the surface rises above its plane (on its front side), sampled at
    // the surface points over its edges' midpoints and its centroid: the chord error.
    std::vector<float> bulge;
    // Per cell of every piece, its two triangles (lower: s ≥ t within the cell, upper: t > s)
    // as indices into `triangles`, or kNoTriangle where the cell's half collapsed to a line (a
    // pole, a disk's centre).
    static constexpr uint32_t kNoTriangle = 0xffffffffu;
    std::vector<uint32_t> slot;
    std::vector<PieceGrid> grids;
};

// The parameters of a tessellation: no triangle edge longer than `max_edge` (0: no limit),
// at least `min_around` cells around a curved piece (revolution, sphere, cap) and `min_along`
// along a sphere's meridians, and, when `max_chord` > 0, cells fine enough that the surface
// lies within max_chord of the triangles (the chord error: a mesh form of the shape within an
// error budget; issue 11), at most `max_cells` per direction of a piece in any case.
struct TessellationOptions {
    float max_edge = 0.0f;
    float max_chord = 0.0f;
    uint32_t min_around = 16;
    uint32_t min_along = 8;
    uint32_t max_cells = 256;  // per direction of a piece
};

void tessellate(const SurfacePieces& pieces, const TessellationOptions& options,
                TessellatedMesh& out);

// The chord error of a piece's grid: the largest distance of a cell side's midpoint chord from
// the surface along s, plus that along t (what `max_chord` bounds, half each way). Unlike
// TessellatedMesh::bulge it includes the in-plane error of a curved rim (a disk's polygon).
double grid_chord_error(const SurfacePiece& piece, const PieceGrid& grid);

// Where a point on (or near) the surface lies: the piece it is nearest to and its (s, t) there,
// clamped into [0, 1]². False when there are no pieces.
struct PiecePoint {
    uint32_t piece = 0;
    double s = 0.0, t = 0.0;
};
bool locate(const SurfacePieces& pieces, const Vec3& position, PiecePoint& out);

// The triangle of the grid that holds (s, t) (its index in `triangles`) and the weights of its
// three corners (indices into `positions`): barycentric in the cell's (s, t).
struct CellPoint {
    std::array<uint32_t, 3> vertices{};
    std::array<float, 3> weights{};
    uint32_t triangle = TessellatedMesh::kNoTriangle;
};
CellPoint cell_point(const TessellatedMesh& mesh, const PiecePoint& p);

}  // namespace rayo
