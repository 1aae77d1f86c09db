#include "core/shapes/mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "core/shapes/polygon_triangulation.h"

namespace rayo {
namespace {

// The checks both add_*_polygon make before adding anything.
bool acceptable_polygon(const std::vector<Vec3>& vertices,
                        const std::vector<Vec3>& vertex_normals) {
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
    return glm::length(area_vector) > 0.0f;
}

// Appends the polygon's vertices (and normals) and the given triangles of it, skipping those of
// zero area.
void append_polygon(TriangleMesh& mesh, const std::vector<Vec3>& vertices,
                    const std::vector<Vec3>& vertex_normals,
                    const std::vector<PolygonTriangle>& polygon_triangles, uint32_t material) {
    const bool with_normals = !vertex_normals.empty();
    if (with_normals && mesh.normals.size() != mesh.positions.size()) {
        mesh.normals.resize(mesh.positions.size(),
                            Vec3(0.0f));  // earlier flat faces: zero = use Ng
    }
    const auto first = static_cast<uint32_t>(mesh.positions.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        mesh.positions.push_back(vertices[i]);
        if (with_normals) {
            mesh.normals.push_back(vertex_normals[i]);
        } else if (!mesh.normals.empty()) {
            mesh.normals.push_back(Vec3(0.0f));
        }
    }
    for (const PolygonTriangle& t : polygon_triangles) {
        const Vec3 e1 = vertices[t[1]] - vertices[t[0]], e2 = vertices[t[2]] - vertices[t[0]];
        if (!(glm::length(glm::cross(e1, e2)) > 0.0f)) continue;  // skip slivers
        mesh.triangles.push_back({first + t[0], first + t[1], first + t[2]});
        mesh.materials.push_back(material);
    }
}

}  // namespace

bool TriangleMesh::add_convex_polygon(const std::vector<Vec3>& vertices,
                                      const std::vector<Vec3>& vertex_normals, uint32_t material) {
    if (!acceptable_polygon(vertices, vertex_normals)) return false;
    std::vector<PolygonTriangle> fan;
    for (uint32_t i = 1; i + 1 < vertices.size(); ++i) fan.push_back({0, i, i + 1});
    append_polygon(*this, vertices, vertex_normals, fan, material);
    return true;
}

bool TriangleMesh::add_polygon(const std::vector<Vec3>& vertices,
                               const std::vector<Vec3>& vertex_normals, uint32_t material) {
    if (!acceptable_polygon(vertices, vertex_normals)) return false;
    const std::vector<PolygonTriangle> triangles = triangulate_polygon(vertices);
    if (triangles.empty()) return false;  // no area in double precision either
    append_polygon(*this, vertices, vertex_normals, triangles, material);
    return true;
}

void TriangleMesh::outline(Outline& out) const {
    // One id per distinct position: NFF polygons and OBJ faces with split normals bring their
    // own copies of shared corners.
    const auto key = [&](uint32_t i) {
        return std::make_tuple(positions[i].x, positions[i].y, positions[i].z);
    };
    std::vector<uint32_t> order(positions.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
    std::vector<uint32_t> id(positions.size());
    for (size_t k = 0; k < order.size(); ++k) {
        id[order[k]] = k > 0 && key(order[k]) == key(order[k - 1]) ? id[order[k - 1]] : order[k];
    }

    struct Edge {
        uint32_t lo, hi, triangle;
    };
    std::vector<Edge> edges;
    edges.reserve(triangles.size() * 3);
    for (uint32_t t = 0; t < triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = id[triangles[t][k]], b = id[triangles[t][(k + 1) % 3]];
            if (a != b) edges.push_back({std::min(a, b), std::max(a, b), t});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
        return std::tie(a.lo, a.hi, a.triangle) < std::tie(b.lo, b.hi, b.triangle);
    });

    const auto normal = [&](uint32_t t) {
        const DVec3 p0(positions[triangles[t][0]]), p1(positions[triangles[t][1]]),
            p2(positions[triangles[t][2]]);
        return glm::cross(p1 - p0, p2 - p0);
    };
    // Normals within about 1e-5 radians of each other and facing the same way.
    const auto coplanar = [&](uint32_t s, uint32_t t) {
        const DVec3 m = normal(s), n = normal(t);
        const double scale = glm::length(m) * glm::length(n);
        return scale > 0.0 && glm::dot(m, n) > 0.0 && glm::length(glm::cross(m, n)) <= 1e-5 * scale;
    };
    for (size_t i = 0; i < edges.size();) {
        size_t j = i + 1;
        while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
        if (!(j - i == 2 && coplanar(edges[i].triangle, edges[i + 1].triangle))) {
            out.add_segment(DVec3(positions[edges[i].lo]), DVec3(positions[edges[i].hi]));
        }
        i = j;
    }
}

}  // namespace rayo
