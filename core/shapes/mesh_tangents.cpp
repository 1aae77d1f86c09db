#include "core/shapes/mesh_tangents.h"

#include <cmath>

namespace rayo {

size_t compute_tangents(TriangleMesh& mesh) {
    const size_t n = mesh.positions.size();
    if (mesh.uvs.size() != n) return 0;
    if (mesh.tangents.size() != n) mesh.tangents.assign(n, glm::vec4(0.0f));
    const bool vertex_normals = mesh.normals.size() == n;
    std::vector<glm::dvec3> du(n, glm::dvec3(0.0)), dv(n, glm::dvec3(0.0)),
        face_normals(n, glm::dvec3(0.0));
    for (const auto& tri : mesh.triangles) {
        const glm::dvec3 p0(mesh.positions[tri[0]]);
        const glm::dvec3 e1 = glm::dvec3(mesh.positions[tri[1]]) - p0;
        const glm::dvec3 e2 = glm::dvec3(mesh.positions[tri[2]]) - p0;
        const glm::dvec2 t0(mesh.uvs[tri[0]]);
        const glm::dvec2 d1 = glm::dvec2(mesh.uvs[tri[1]]) - t0;
        const glm::dvec2 d2 = glm::dvec2(mesh.uvs[tri[2]]) - t0;
        const glm::dvec3 area_normal = glm::cross(e1, e2);
        for (uint32_t v : tri) face_normals[v] += area_normal;
        // Lengyel 2001: [e1 e2] = [T B]·[[s1 s2] [t1 t2]] solved for T = ∂p/∂s, B = ∂p/∂t.
        const double determinant = d1.x * d2.y - d2.x * d1.y;
        if (!(std::abs(determinant) > 1e-20)) continue;  // collinear texture coordinates
        const double r = 1.0 / determinant;
        const glm::dvec3 s_direction = (d2.y * e1 - d1.y * e2) * r;
        const glm::dvec3 t_direction = (d1.x * e2 - d2.x * e1) * r;
        for (uint32_t v : tri) {
            du[v] += s_direction;
            dv[v] += t_direction;
        }
    }
    size_t filled = 0;
    for (size_t v = 0; v < n; ++v) {
        if (mesh.tangents[v].w != 0.0f) continue;
        glm::dvec3 normal = vertex_normals ? glm::dvec3(mesh.normals[v]) : glm::dvec3(0.0);
        if (glm::dot(normal, normal) == 0.0) normal = face_normals[v];
        const double normal_length = glm::length(normal);
        if (!(normal_length > 0.0)) continue;
        normal /= normal_length;
        // Gram-Schmidt: T' = normalize(T − N(N·T)).
        const glm::dvec3 tangent = du[v] - normal * glm::dot(normal, du[v]);
        const double length = glm::length(tangent);
        if (!(length > 0.0) || !std::isfinite(length)) continue;
        // The bitangent the maps mean is the image's up, −∂p/∂t (t grows down the image).
        const double w = glm::dot(glm::cross(normal, tangent), -dv[v]) < 0.0 ? -1.0 : 1.0;
        mesh.tangents[v] = glm::vec4(glm::vec3(tangent / length), static_cast<float>(w));
        ++filled;
    }
    return filled;
}

}  // namespace rayo
