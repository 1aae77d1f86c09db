#include "core/shapes/mesh_geometry.h"

#include <cmath>

#include "core/embree_device.h"
#include "core/shadow_terminator.h"

namespace rayo {
namespace {

Vec3 triangle_normal(const TriangleMesh& mesh, uint32_t prim) {
    const auto& tri = mesh.triangles[prim];
    const Vec3& p0 = mesh.positions[tri[0]];
    // Right-handed: counter-clockwise vertices seen from the side the normal points to.
    return glm::cross(mesh.positions[tri[1]] - p0, mesh.positions[tri[2]] - p0);
}

// One-sided meshes: reject hits on the back of a triangle (NFF polygons, docs/nff.md).
void cull_back_faces(const RTCFilterFunctionNArguments* args) {
    const auto* mesh = static_cast<const TriangleMesh*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const Vec3 direction(RTCRayN_dir_x(args->ray, args->N, i),
                             RTCRayN_dir_y(args->ray, args->N, i),
                             RTCRayN_dir_z(args->ray, args->N, i));
        const uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
        if (glm::dot(triangle_normal(*mesh, prim), direction) >= 0.0f) args->valid[i] = 0;
    }
}

// The texture coordinates of the point of triangle `prim` at barycentrics (b1, b2): interpolated
// from the mesh's, or the barycentrics themselves for a mesh without.
glm::vec2 texture_coordinates(const TriangleMesh& mesh, uint32_t prim, float b1, float b2) {
    if (mesh.uvs.size() != mesh.positions.size()) return glm::vec2(b1, b2);
    const auto& tri = mesh.triangles[prim];
    return (1.0f - b1 - b2) * mesh.uvs[tri[0]] + b1 * mesh.uvs[tri[1]] + b2 * mesh.uvs[tri[2]];
}

// What the cutout filter needs: the mesh and the test.
struct CutoutFilter {
    const TriangleMesh* mesh = nullptr;
    const CutoutTest* cutouts = nullptr;
};

// Meshes with holes (core/cutout.h): reject hits where the material has a hole, and, for
// one-sided meshes, on the back of a triangle (cull_back_faces). Registered only on such meshes.
void cut_holes(const RTCFilterFunctionNArguments* args) {
    const auto* filter = static_cast<const CutoutFilter*>(args->geometryUserPtr);
    const TriangleMesh& mesh = *filter->mesh;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
        if (mesh.one_sided) {
            const Vec3 direction(RTCRayN_dir_x(args->ray, args->N, i),
                                 RTCRayN_dir_y(args->ray, args->N, i),
                                 RTCRayN_dir_z(args->ray, args->N, i));
            if (glm::dot(triangle_normal(mesh, prim), direction) >= 0.0f) {
                args->valid[i] = 0;
                continue;
            }
        }
        const uint32_t material = mesh.materials[prim];
        if (!filter->cutouts->cuts(material)) continue;
        const glm::vec2 uv = texture_coordinates(mesh, prim, RTCHitN_u(args->hit, args->N, i),
                                                 RTCHitN_v(args->hit, args->N, i));
        if (filter->cutouts->hole(material, uv)) args->valid[i] = 0;
    }
}

class MeshBinding : public GeometryBinding {
  public:
    MeshBinding(const TriangleMesh& mesh, uint32_t mesh_index, uint32_t shape_index,
                const CutoutTest* cutouts)
        : m_mesh(mesh), m_mesh_index(mesh_index), m_shape_index(shape_index) {
        m_geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_TRIANGLE);
        // Copies into Embree-owned buffers: Embree reads vertices as 16 bytes, so a shared
        // std::vector<Vec3> would be over-read at its end.
        auto* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(m_geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    sizeof(float) * 3, mesh.positions.size()));
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            vertices[3 * v + 0] = mesh.positions[v].x;
            vertices[3 * v + 1] = mesh.positions[v].y;
            vertices[3 * v + 2] = mesh.positions[v].z;
        }
        auto* indices = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(m_geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    sizeof(unsigned) * 3, mesh.triangles.size()));
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            indices[3 * t + 0] = mesh.triangles[t][0];
            indices[3 * t + 1] = mesh.triangles[t][1];
            indices[3 * t + 2] = mesh.triangles[t][2];
        }
        if (cutouts) {
            m_cutout.mesh = &mesh;
            m_cutout.cutouts = cutouts;
            rtcSetGeometryUserData(m_geometry, &m_cutout);
            rtcSetGeometryIntersectFilterFunction(m_geometry, cut_holes);
            rtcSetGeometryOccludedFilterFunction(m_geometry, cut_holes);
        } else if (mesh.one_sided) {
            rtcSetGeometryUserData(m_geometry, const_cast<TriangleMesh*>(&mesh));
            rtcSetGeometryIntersectFilterFunction(m_geometry, cull_back_faces);
            rtcSetGeometryOccludedFilterFunction(m_geometry, cull_back_faces);
        }
    }
    RTCGeometry geometry() const override { return m_geometry; }
    size_t primitive_count() const override { return m_mesh.triangles.size(); }

    void surface(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& out) const override {
        const TriangleMesh& mesh = m_mesh;
        const float t = rayhit.ray.tfar;
        const uint32_t prim = rayhit.hit.primID;
        const auto& tri = mesh.triangles[prim];
        out.t = t;
        out.position = ray.at(t);
        out.geometric_normal = unit_vector(triangle_normal(mesh, prim));
        out.shading_normal = out.geometric_normal;
        // Interpolate vertex normals only where all three corners have one (a zero normal
        // marks a corner without: flat faces mixed into a smooth mesh).
        if (!mesh.normals.empty() && mesh.normals[tri[0]] != Vec3(0.0f) &&
            mesh.normals[tri[1]] != Vec3(0.0f) && mesh.normals[tri[2]] != Vec3(0.0f)) {
            const float u = rayhit.hit.u, v = rayhit.hit.v;
            const Vec3 n = (1.0f - u - v) * mesh.normals[tri[0]] + u * mesh.normals[tri[1]] +
                           v * mesh.normals[tri[2]];
            const float length = glm::length(n);
            if (length > 0.0f) {
                // Keep the interpolated normal on the geometric normal's side.
                const Vec3 unit = n / length;
                const float side = glm::dot(unit, out.geometric_normal) >= 0.0f ? 1.0f : -1.0f;
                out.shading_normal = side * unit;
                const Vec3 corners[3] = {mesh.positions[tri[0]], mesh.positions[tri[1]],
                                         mesh.positions[tri[2]]};
                const Vec3 normals[3] = {side * mesh.normals[tri[0]], side * mesh.normals[tri[1]],
                                         side * mesh.normals[tri[2]]};
                const float weights[3] = {1.0f - u - v, u, v};
                out.terminator_offset = terminator_offset(out.position, corners, normals, weights);
            }
        }
        if (!mesh.colors.empty() && mesh.colors.size() == mesh.positions.size()) {
            const float u = rayhit.hit.u, v = rayhit.hit.v;
            out.vertex_color = (1.0f - u - v) * mesh.colors[tri[0]] + u * mesh.colors[tri[1]] +
                               v * mesh.colors[tri[2]];
        }
        const Vec3& p0 = mesh.positions[tri[0]];
        out.object_size = glm::max(glm::length(mesh.positions[tri[1]] - p0),
                                   glm::length(mesh.positions[tri[2]] - p0));
        out.material = mesh.materials[prim];
        out.shape = m_shape_index;
        out.primitive = prim;
        out.mesh = m_mesh_index;
        // Barycentrics kept for parameterize().
        out.uv = glm::vec2(rayhit.hit.u, rayhit.hit.v);
    }

    void parameterize(SurfaceHit& hit) const override {
        const auto& tri = m_mesh.triangles[hit.primitive];
        const Vec3& p0 = m_mesh.positions[tri[0]];
        const Vec3 e1 = m_mesh.positions[tri[1]] - p0, e2 = m_mesh.positions[tri[2]] - p0;
        if (m_mesh.uvs.size() != m_mesh.positions.size()) {
            // Without texture coordinates: the barycentric (u, v) of the hit, and
            // ∂p/∂u = p1 − p0.
            hit.dpdu = e1;
            return;
        }
        // hit.uv holds the barycentrics surface() kept.
        const float b1 = hit.uv.x, b2 = hit.uv.y;
        const glm::vec2 &t0 = m_mesh.uvs[tri[0]], &t1 = m_mesh.uvs[tri[1]],
                        &t2 = m_mesh.uvs[tri[2]];
        hit.uv = texture_coordinates(m_mesh, hit.primitive, b1, b2);
        if (m_mesh.tangents.size() == m_mesh.positions.size()) {
            const glm::vec4 &a = m_mesh.tangents[tri[0]], &b = m_mesh.tangents[tri[1]],
                            &c = m_mesh.tangents[tri[2]];
            // Interpolated where all three corners have one (w = 0 marks a corner without);
            // the handedness is the first corner's (a mirrored seam has split vertices).
            if (a.w != 0.0f && b.w != 0.0f && c.w != 0.0f) {
                hit.tangent = glm::vec4(
                    (1.0f - b1 - b2) * glm::vec3(a) + b1 * glm::vec3(b) + b2 * glm::vec3(c), a.w);
            }
        }
        // The tangents solve [e1 e2] = [∂p/∂u ∂p/∂v]·[Δuv1 Δuv2] (pbrt 3, section 3.6.2); a
        // triangle whose texture coordinates are collinear has none: the edges stand in.
        const glm::vec2 d1 = t1 - t0, d2 = t2 - t0;
        const float determinant = d1.x * d2.y - d1.y * d2.x;
        if (std::abs(determinant) > 1e-12f) {
            const float inverse = 1.0f / determinant;
            hit.dpdu = (d2.y * e1 - d1.y * e2) * inverse;
            hit.dpdv = (d1.x * e2 - d2.x * e1) * inverse;
        } else {
            hit.dpdu = e1;
            hit.dpdv = e2;
        }
    }

  private:
    const TriangleMesh& m_mesh;
    uint32_t m_mesh_index;
    uint32_t m_shape_index;
    CutoutFilter m_cutout;
    RTCGeometry m_geometry = nullptr;
};

}  // namespace

std::unique_ptr<GeometryBinding> make_mesh_binding(const TriangleMesh& mesh, uint32_t mesh_index,
                                                   uint32_t shape_index,
                                                   const CutoutTest* cutouts) {
    return std::make_unique<MeshBinding>(mesh, mesh_index, shape_index, cutouts);
}

bool mesh_has_cutout(const TriangleMesh& mesh, const CutoutTest& cutouts) {
    uint32_t last = 0;
    bool known = false;
    for (uint32_t material : mesh.materials) {
        if (known && material == last) continue;
        if (cutouts.cuts(material)) return true;
        last = material;
        known = true;
    }
    return false;
}

}  // namespace rayo
