#include "core/shapes/mesh.h"

#include <cmath>

namespace rayo {

bool TriangleMesh::add_convex_polygon(const std::vector<Vec3>& vertices,
                                      const std::vector<Vec3>& vertex_normals,
                                      uint32_t material) {
    if (vertices.size() < 3) return false;
    if (!vertex_normals.empty() && vertex_normals.size() != vertices.size()) return false;
    for (const Vec3& v : vertices) {
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
    }
    // Reject polygons whose fan has no area (all vertices collinear or coincident).
    Vec3 area_vector(0.0f);
    for (size_t i = 1; i + 1 < vertices.size(); ++i) {
        area_vector += glm::cross(vertices[i] - vertices[0], vertices[i + 1] - vertices[0]);
    }
    if (!(glm::length(area_vector) > 0.0f)) return false;

    const bool with_normals = !vertex_normals.empty();
    if (with_normals && normals.size() != positions.size()) {
        normals.resize(positions.size(), Vec3(0.0f));  // earlier flat faces: zero = use Ng
    }
    const auto first = static_cast<uint32_t>(positions.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        positions.push_back(vertices[i]);
        if (with_normals) {
            normals.push_back(vertex_normals[i]);
        } else if (!normals.empty()) {
            normals.push_back(Vec3(0.0f));
        }
    }
    for (size_t i = 1; i + 1 < vertices.size(); ++i) {
        const Vec3 e1 = vertices[i] - vertices[0], e2 = vertices[i + 1] - vertices[0];
        if (!(glm::length(glm::cross(e1, e2)) > 0.0f)) continue;  // skip slivers in the fan
        triangles.push_back({first, first + static_cast<uint32_t>(i),
                             first + static_cast<uint32_t>(i + 1)});
        materials.push_back(material);
    }
    return true;
}

}  // namespace rayo
