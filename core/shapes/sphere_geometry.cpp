#include "core/shapes/sphere_geometry.h"

#include <limits>
#include <stdexcept>

#include "core/shadow_terminator.h"
#include "core/shapes/icosphere.h"
#include "core/user_geometry.h"

namespace rayo {
namespace {

template <SphereMath kMath>
struct SphereNearest {
    static bool run(const Sphere& s, const Vec3& origin, const Vec3& direction, float tnear,
                    float tfar, ShapeHit& hit) {
        return s.nearest<kMath>(origin, direction, tnear, tfar, hit);
    }
};

// Embree's RTC_GEOMETRY_TYPE_SPHERE_POINT: its own kernel, rayo's re-projected surface.
class PointSphereBinding : public ShapeSurfaceBinding<Sphere> {
  public:
    PointSphereBinding(const std::vector<Sphere>& spheres, uint32_t shape_index)
        : ShapeSurfaceBinding<Sphere>(spheres, shape_index) {
        m_geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* points = static_cast<float*>(
            rtcSetNewGeometryBuffer(m_geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                    4 * sizeof(float), spheres.size()));
        for (size_t i = 0; i < spheres.size(); ++i) {
            points[4 * i + 0] = spheres[i].center.x;
            points[4 * i + 1] = spheres[i].center.y;
            points[4 * i + 2] = spheres[i].center.z;
            points[4 * i + 3] = spheres[i].radius;
        }
    }
};

// Each sphere tessellated into an icosphere of Embree triangles. The tessellation is the
// surface: no re-projection, so its silhouette and facet error show in the image, which is what
// the comparison measures.
class IcosphereBinding : public GeometryBinding {
  public:
    IcosphereBinding(const std::vector<Sphere>& spheres, uint32_t shape_index,
                     const SphereRepresentation& representation)
        : m_spheres(spheres), m_shape_index(shape_index), m_smooth(representation.mesh_smooth) {
        Icosphere unit = make_icosphere(representation.mesh_level);
        m_triangles_per_sphere = static_cast<uint32_t>(unit.triangles.size());
        const size_t vertex_count = unit.positions.size();
        m_geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(m_geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    3 * sizeof(float), spheres.size() * vertex_count));
        auto* indices = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(m_geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), spheres.size() * unit.triangles.size()));
        for (size_t i = 0; i < spheres.size(); ++i) {
            for (size_t v = 0; v < vertex_count; ++v) {
                const Vec3 p = spheres[i].center + spheres[i].radius * unit.positions[v];
                float* out = vertices + 3 * (i * vertex_count + v);
                out[0] = p.x;
                out[1] = p.y;
                out[2] = p.z;
            }
            const auto first = static_cast<unsigned>(i * vertex_count);
            unsigned* out = indices + 3 * i * unit.triangles.size();
            for (const auto& t : unit.triangles) {
                *out++ = first + t[0];
                *out++ = first + t[1];
                *out++ = first + t[2];
            }
        }
        m_normals = std::move(unit.positions);
        m_triangles = std::move(unit.triangles);
    }
    RTCGeometry geometry() const override { return m_geometry; }
    size_t primitive_count() const override { return m_spheres.size() * m_triangles_per_sphere; }
    void surface(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& out) const override {
        const float t = rayhit.ray.tfar;
        const uint32_t prim = rayhit.hit.primID;
        const uint32_t sphere = prim / m_triangles_per_sphere;
        const auto& tri = m_triangles[prim % m_triangles_per_sphere];
        const Vec3& n0 = m_normals[tri[0]];
        const Vec3 flat =
            glm::normalize(glm::cross(m_normals[tri[1]] - n0, m_normals[tri[2]] - n0));
        out.t = t;
        out.position = ray.at(t);
        out.geometric_normal = flat;
        out.shading_normal = flat;
        if (m_smooth) {
            const float u = rayhit.hit.u, v = rayhit.hit.v;
            out.shading_normal =
                glm::normalize((1.0f - u - v) * n0 + u * m_normals[tri[1]] + v * m_normals[tri[2]]);
            // The icosphere's corners are centre + radius·n_i with the unit n_i as normals.
            const Sphere& s = m_spheres[sphere];
            const Vec3 normals[3] = {n0, m_normals[tri[1]], m_normals[tri[2]]};
            const Vec3 corners[3] = {s.center + s.radius * normals[0],
                                     s.center + s.radius * normals[1],
                                     s.center + s.radius * normals[2]};
            const float weights[3] = {1.0f - u - v, u, v};
            out.terminator_offset = terminator_offset(out.position, corners, normals, weights);
        }
        out.object_size = m_spheres[sphere].radius;
        out.material = m_spheres[sphere].material;
        out.shape = m_shape_index;
        out.primitive = sphere;
    }
    void parameterize(SurfaceHit& hit) const override {
        m_spheres[hit.primitive].parameterization(hit.position, hit);
    }

  private:
    const std::vector<Sphere>& m_spheres;
    uint32_t m_shape_index;
    bool m_smooth;
    uint32_t m_triangles_per_sphere = 0;
    std::vector<Vec3> m_normals;  // of the unit icosphere
    std::vector<std::array<uint32_t, 3>> m_triangles;
    RTCGeometry m_geometry = nullptr;
};

// Brute force, the reference: every sphere as a part of one aggregate primitive whose bounds
// hold them all, traced by the generic callbacks; nearest() tests every sphere in order (the
// window shrinking to the nearest so far) and reports the sphere as the hit's part.
struct AllSpheres {
    const std::vector<Sphere>* spheres = nullptr;
    SphereMath math = SphereMath::Stable;
    Bounds3 box;

    Bounds3 bounds() const { return box; }
    bool nearest(const Vec3& origin, const Vec3& direction, float tnear, float tfar,
                 ShapeHit& hit) const {
        bool found = false;
        const auto count = static_cast<uint32_t>(spheres->size());
        for (uint32_t i = 0; i < count; ++i) {
            const Sphere& s = (*spheres)[i];
            float t;
            bool far_root;
            if (intersect_sphere(math, origin, direction, s.center, s.radius, tnear, tfar, t,
                                 far_root)) {
                tfar = t;
                hit.t = t;
                hit.part = i;
                found = true;
            }
        }
        return found;
    }
};

class BruteForceBinding : public ShapeSurfaceBinding<Sphere> {
  public:
    BruteForceBinding(const std::vector<Sphere>& spheres, uint32_t shape_index, SphereMath math)
        : ShapeSurfaceBinding<Sphere>(spheres, shape_index) {
        m_all.spheres = &spheres;
        m_all.math = math;
        m_all.box = spheres.front().bounds();
        for (const Sphere& s : spheres) {
            const Bounds3 b = s.bounds();
            m_all.box.lower = glm::min(m_all.box.lower, b.lower);
            m_all.box.upper = glm::max(m_all.box.upper, b.upper);
        }
        m_data.shapes = m_data.intersectors = &m_all;
        m_geometry = new_user_geometry<AllSpheres>(1, &m_data);
    }

  private:
    AllSpheres m_all;
    UserGeometryData<AllSpheres> m_data;
};

}  // namespace

std::unique_ptr<GeometryBinding> make_binding(const std::vector<Sphere>& spheres,
                                              uint32_t shape_index, const AccelOptions& options) {
    switch (options.spheres.method) {
        case SphereMethod::User:
            switch (options.sphere_math) {
                case SphereMath::Seed:
                    return std::make_unique<ShapeBinding<Sphere, SphereNearest<SphereMath::Seed>>>(
                        spheres, shape_index);
                case SphereMath::Double:
                    return std::make_unique<
                        ShapeBinding<Sphere, SphereNearest<SphereMath::Double>>>(spheres,
                                                                                 shape_index);
                case SphereMath::Stable:
                    break;
            }
            return std::make_unique<ShapeBinding<Sphere, SphereNearest<SphereMath::Stable>>>(
                spheres, shape_index);
        case SphereMethod::EmbreePoint:
            return std::make_unique<PointSphereBinding>(spheres, shape_index);
        case SphereMethod::Mesh:
            return std::make_unique<IcosphereBinding>(spheres, shape_index, options.spheres);
        case SphereMethod::BruteForce:
            return std::make_unique<BruteForceBinding>(spheres, shape_index, options.sphere_math);
        case SphereMethod::Auto:
            break;
    }
    throw std::logic_error("Accel: the auto sphere method must be resolved by the caller");
}

}  // namespace rayo
