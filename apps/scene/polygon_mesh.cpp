#include "apps/scene/polygon_mesh.h"

#include <cmath>
#include <utility>

#include "core/shapes/polygon_triangulation.h"

namespace rayo {

Vec3 unit_normal_or_zero(const Vec3& normal) {
    const float length = glm::length(normal);
    return std::isfinite(length) && length > 0.0f ? normal / length : Vec3(0.0f);
}

TriangleMesh triangulate_polygon_mesh(PolygonMesh&& polygons, uint32_t material) {
    TriangleMesh mesh;
    std::vector<Vec3> outline;
    uint32_t start = 0;
    for (const uint32_t end : polygons.face_ends) {
        const uint32_t* corner = polygons.corners.data() + start;
        const size_t count = end - start;
        start = end;
        if (count == 3) {
            mesh.triangles.push_back({corner[0], corner[1], corner[2]});
            continue;
        }
        if (count < 3) continue;  // a point or a line
        outline.clear();
        for (size_t k = 0; k < count; ++k) outline.push_back(polygons.positions[corner[k]]);
        for (const PolygonTriangle& t : triangulate_polygon(outline)) {
            mesh.triangles.push_back({corner[t[0]], corner[t[1]], corner[t[2]]});
        }
    }
    std::vector<uint32_t>().swap(polygons.corners);
    std::vector<uint32_t>().swap(polygons.face_ends);
    mesh.materials.assign(mesh.triangles.size(), material);
    mesh.positions = std::move(polygons.positions);
    mesh.normals = std::move(polygons.normals);
    mesh.colors = std::move(polygons.colors);
    polygons = PolygonMesh();
    return mesh;
}

}  // namespace rayo
