#pragma once
// A triangle mesh as Embree consumes it: shared vertex positions, optional per-vertex normals
// (NFF `pp` patches, smooth OBJ/glTF meshes) and one material id per triangle.
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/shapes/outline.h"

namespace rayo {

struct TriangleMesh {
    std::string name;
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // empty, or one per position
    // Empty, or one linear RGB colour per position that multiplies the material's kd and ka
    // (glTF COLOR_0, OBJ `v x y z r g b`), interpolated across each triangle.
    std::vector<Vec3> colors;
    // Empty, or one texture coordinate per position (OBJ `vt`, glTF TEXCOORD_0), in the image
    // convention (0, 0) = the image's top-left corner (OBJ's v is flipped on reading); hits get
    // them interpolated by Accel::parameterize.
    std::vector<glm::vec2> uvs;
    // Empty, or one tangent per position for normal maps (glTF TANGENT, or computed:
    // core/shapes/mesh_tangents.h): xyz the direction of increasing u, w = ±1 the handedness,
    // the bitangent (the image's "up", decreasing t) being w·(normal × tangent). w = 0 marks a
    // vertex without one.
    std::vector<glm::vec4> tangents;
    std::vector<std::array<uint32_t, 3>> triangles;
    std::vector<uint32_t> materials;  // one per triangle
    // Two-sided meshes are hit from both sides (shading faces the normal forward). A one-sided
    // mesh is seen only from the side its counter-clockwise winding faces (NFF polygons without
    // transmission, docs/nff.md); back-facing hits are ignored by every ray.
    bool one_sided = false;

    size_t triangle_count() const { return triangles.size(); }
    // Appends a convex polygon as a triangle fan; returns false (adding nothing) when it has
    // fewer than three vertices, a non-finite coordinate, a normal count other than zero or
    // one per vertex, or all its triangles are degenerate (zero area).
    bool add_convex_polygon(const std::vector<Vec3>& vertices,
                            const std::vector<Vec3>& vertex_normals, uint32_t material);
    // Appends a simple planar polygon, convex or concave (NFF polygons,
    // core/shapes/polygon_triangulation.h): convex ones as the same fan as add_convex_polygon,
    // others ear-clipped; triangles keep the polygon's winding and zero-area ones are dropped.
    // Returns false (adding nothing) in the same cases as add_convex_polygon.
    bool add_polygon(const std::vector<Vec3>& vertices, const std::vector<Vec3>& vertex_normals,
                     uint32_t material);
    // The wireframe (core/shapes/outline.h): every edge once, vertices at one position counted
    // as one; an edge between two coplanar triangles that face the same way (the inside of a
    // triangulated polygon) is left out.
    void outline(Outline& out) const;
};

}  // namespace rayo
