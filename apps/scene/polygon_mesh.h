#pragma once
// Polygons as rayo's PLY, STL and OFF readers give them (apps/scene/ply_reader.h, stl_reader.h,
// off_reader.h), before they become triangles: the vertices with their optional normals and
// colours, and the faces as lists of vertex indices that the readers have checked.
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "core/shapes/mesh.h"

namespace rayo {

struct PolygonMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // empty, or one per position (unit length, or zero: none)
    std::vector<Vec3> colors;   // empty, or one per position (linear RGB, finite, >= 0)
    // The faces' vertex indices, face after face: face f is corners[face_ends[f - 1] ..
    // face_ends[f]) (from 0 for f = 0). Every index is below positions.size() once the reader
    // is done; a face may have one or two corners (a point, a line: not surfaces, dropped).
    std::vector<uint32_t> corners;
    std::vector<uint32_t> face_ends;

    // Closes the face made of the corners appended since the last one.
    void end_face() { face_ends.push_back(static_cast<uint32_t>(corners.size())); }
};

// The normal as a file gives it, made unit length; zero (no normal: shade with the geometric
// normal) when it is zero or not finite.
Vec3 unit_normal_or_zero(const Vec3& normal);

// The triangles of `polygons` with `material`: a face of three corners as it is, a larger one
// triangulated (core/shapes/polygon_triangulation.h: the fan for a convex face, ear clipping for
// a concave one), faces of one or two corners dropped. Positions, normals and colours move into
// the mesh; `polygons` is left empty. The caller drops degenerate triangles.
TriangleMesh triangulate_polygon_mesh(PolygonMesh&& polygons, uint32_t material);

}  // namespace rayo
