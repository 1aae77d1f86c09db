#include "core/shapes/marching_tetrahedra.h"

#include <unordered_map>

namespace rayo {
namespace {

class Tessellator {
  public:
    Tessellator(const SampledField& field, uint32_t material, const std::string& name)
        : m_field(field), m_g(field.samples), m_material(material) {
        for (int axis = 0; axis < 3; ++axis) m_n[axis] = field.counts[axis];
        m_mesh.name = name;
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
    DVec3 point(int i, int j, int k) const { return m_field.lower + m_field.cell * DVec3(i, j, k); }

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
        for (const auto& tet : kCubeTetrahedra) {
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
        m_mesh.normals.push_back(m_field.outward(position));
        m_vertices.emplace(key, id);
        return id;
    }

    // A triangle wound counter-clockwise seen from outside (its face normal along `outward`).
    void triangle(uint32_t a, uint32_t b, uint32_t c) {
        const Vec3 &pa = m_mesh.positions[a], &pb = m_mesh.positions[b], &pc = m_mesh.positions[c];
        const Vec3 face = glm::cross(pb - pa, pc - pa);
        if (glm::dot(face, face) == 0.0f) return;  // degenerate (a corner on the surface)
        const Vec3 outward = m_mesh.normals[a] + m_mesh.normals[b] + m_mesh.normals[c];
        if (glm::dot(face, outward) < 0.0f) std::swap(b, c);
        m_mesh.triangles.push_back({a, b, c});
        m_mesh.materials.push_back(m_material);
    }

    const SampledField& m_field;
    const std::vector<double>& m_g;
    uint32_t m_material;
    int m_n[3];
    std::unordered_map<uint64_t, uint32_t> m_vertices;
    TriangleMesh m_mesh;
};

}  // namespace

TriangleMesh marching_tetrahedra(const SampledField& field, uint32_t material,
                                 const std::string& name) {
    return Tessellator(field, material, name).run();
}

}  // namespace rayo
