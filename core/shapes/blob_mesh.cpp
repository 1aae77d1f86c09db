#include "core/shapes/blob_mesh.h"

#include <cmath>
#include <unordered_map>

namespace rayo {
namespace {

// The cube's corners (bit 0: +x, bit 1: +y, bit 2: +z) and its six tetrahedra around the
// diagonal 0–7: each runs 0 → 7 through two corners that differ in one more axis.
constexpr int kTetrahedra[6][4] = {{0, 7, 1, 3}, {0, 7, 3, 2}, {0, 7, 2, 6},
                                   {0, 7, 6, 4}, {0, 7, 4, 5}, {0, 7, 5, 1}};

class Tessellator {
  public:
    Tessellator(const Blob& blob, double cell) : m_blob(blob), m_cell(cell) {
        const Bounds3 b = blob.bounds();
        m_lower = DVec3(b.lower) - DVec3(cell);
        const DVec3 extent = DVec3(b.upper) - DVec3(b.lower) + DVec3(2.0 * cell);
        for (int axis = 0; axis < 3; ++axis) m_n[axis] = int(std::ceil(extent[axis] / cell)) + 1;
        m_g.resize(static_cast<size_t>(m_n[0]) * m_n[1] * m_n[2]);
        for (int k = 0; k < m_n[2]; ++k) {
            for (int j = 0; j < m_n[1]; ++j) {
                for (int i = 0; i < m_n[0]; ++i) {
                    m_g[index(i, j, k)] = blob.field(point(i, j, k)) - blob.threshold;
                }
            }
        }
        m_mesh.name = "blob";
    }

    TriangleMesh run() {
        for (int k = 0; k + 1 < m_n[2]; ++k) {
            for (int j = 0; j + 1 < m_n[1]; ++j) {
                for (int i = 0; i + 1 < m_n[0]; ++i) cube(i, j, k);
            }
        }
        return std::move(m_mesh);
    }

  private:
    uint64_t index(int i, int j, int k) const {
        return (static_cast<uint64_t>(k) * m_n[1] + j) * m_n[0] + i;
    }
    DVec3 point(int i, int j, int k) const { return m_lower + m_cell * DVec3(i, j, k); }

    void cube(int i, int j, int k) {
        uint64_t id[8];
        DVec3 p[8];
        double g[8];
        int inside = 0;
        for (int c = 0; c < 8; ++c) {
            const int ci = i + (c & 1), cj = j + ((c >> 1) & 1), ck = k + ((c >> 2) & 1);
            id[c] = index(ci, cj, ck);
            p[c] = point(ci, cj, ck);
            g[c] = m_g[id[c]];
            inside += g[c] > 0.0;
        }
        if (inside == 0 || inside == 8) return;
        for (const auto& tet : kTetrahedra) {
            int in[4], out[4], n_in = 0, n_out = 0;
            for (const int c : tet) (g[c] > 0.0 ? in[n_in++] : out[n_out++]) = c;
            const auto v = [&](int a, int b) {
                return vertex(id[a], p[a], g[a], id[b], p[b], g[b]);
            };
            if (n_in == 1 || n_in == 3) {
                const int lone = n_in == 1 ? in[0] : out[0];
                const int* others = n_in == 1 ? out : in;
                triangle(v(lone, others[0]), v(lone, others[1]), v(lone, others[2]));
            } else if (n_in == 2) {
                const uint32_t a = v(in[0], out[0]), b = v(in[0], out[1]), c = v(in[1], out[1]),
                               d = v(in[1], out[0]);
                triangle(a, b, c);
                triangle(a, c, d);
            }
        }
    }

    // The vertex where g crosses 0 on the edge between corners a and b (made once per edge).
    uint32_t vertex(uint64_t a, const DVec3& pa, double ga, uint64_t b, const DVec3& pb,
                    double gb) {
        const uint64_t corners = m_g.size();
        const uint64_t key = a < b ? a * corners + b : b * corners + a;
        const auto found = m_vertices.find(key);
        if (found != m_vertices.end()) return found->second;
        const double s = ga / (ga - gb);  // linear interpolation of g along the edge
        const DVec3 position = pa + s * (pb - pa);
        const uint32_t id = static_cast<uint32_t>(m_mesh.positions.size());
        m_mesh.positions.push_back(Vec3(position));
        const DVec3 outward = -m_blob.gradient(position);
        const double length = glm::length(outward);
        m_mesh.normals.push_back(Vec3(length > 0.0 ? outward / length : DVec3(0.0, 1.0, 0.0)));
        m_vertices.emplace(key, id);
        return id;
    }

    // A triangle wound counter-clockwise seen from outside (its face normal along −∇F).
    void triangle(uint32_t a, uint32_t b, uint32_t c) {
        const Vec3 &pa = m_mesh.positions[a], &pb = m_mesh.positions[b], &pc = m_mesh.positions[c];
        const Vec3 face = glm::cross(pb - pa, pc - pa);
        if (glm::dot(face, face) == 0.0f) return;  // degenerate (a corner on the surface)
        const Vec3 outward = m_mesh.normals[a] + m_mesh.normals[b] + m_mesh.normals[c];
        if (glm::dot(face, outward) < 0.0f) std::swap(b, c);
        m_mesh.triangles.push_back({a, b, c});
        m_mesh.materials.push_back(m_blob.material);
    }

    const Blob& m_blob;
    double m_cell;
    DVec3 m_lower;
    int m_n[3];
    std::vector<double> m_g;
    std::unordered_map<uint64_t, uint32_t> m_vertices;
    TriangleMesh m_mesh;
};

}  // namespace

TriangleMesh tessellate_blob(const Blob& blob, double cell) {
    return Tessellator(blob, cell).run();
}

}  // namespace rayo
