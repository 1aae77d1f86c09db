#pragma once
// The Embree acceleration structure: one committed RTCScene per render holding the spheres and
// cones as user geometry (our own intersection code) and the meshes as Embree triangles.
// Follows the Embree 3 call order: device -> scene -> geometries -> commit, then trace.
#include <cstdint>
#include <array>
#include <atomic>
#include <memory>
#include <vector>

#include <embree3/rtcore.h>

#include "core/ray.h"
#include "core/scene.h"
#include "core/sphere_method.h"

namespace rayo {

struct AccelOptions {
    SphereRepresentation spheres;                 // method; Auto must be resolved before
    SphereMath sphere_math = SphereMath::Stable;  // for the analytic methods (user, bruteforce)
    bool robust = true;  // RTC_SCENE_FLAG_ROBUST: watertight triangles (DESIGN.md)
};

enum class PrimitiveKind : uint8_t { Sphere, Cone, Triangle };

// What the shader needs to know about the nearest hit.
struct SurfaceHit {
    float t = 0.0f;
    Vec3 position{0.0f};         // on the surface (sphere hits re-projected onto the sphere)
    Vec3 geometric_normal{0.0f}; // unit, outward (spheres, cones) or by winding (triangles)
    Vec3 shading_normal{0.0f};   // unit, interpolated where the mesh has normals; same side as Ng
    float object_size = 0.0f;    // radius or triangle extent: scales the spawned-ray offset
    uint32_t material = 0;
    PrimitiveKind kind = PrimitiveKind::Sphere;
    uint32_t primitive = 0;  // index of the sphere, the cone, or the triangle within its mesh
    uint32_t mesh = 0;       // the mesh's index, for triangles
};

struct AccelUserData;

class Accel {
public:
    Accel(const Scene& scene, const AccelOptions& options = {});
    ~Accel();
    Accel(const Accel&) = delete;
    Accel& operator=(const Accel&) = delete;

    bool intersect(const Ray& ray, SurfaceHit& hit) const;
    // True when anything lies on the ray within (tnear, tfar).
    bool occluded(const Ray& ray) const;

    // Coherent batches (a tile's camera rays, its shadow rays toward one light) go through
    // Embree ray streams (rtcIntersect1M/rtcOccluded1M, COHERENT flag), which traverse them as
    // packets. Ray by ray the results equal intersect()/occluded() (tests/accel_test.cpp).
    void intersect_coherent(const Ray* rays, int count, SurfaceHit* hits, bool* found) const;
    void occluded_coherent(const Ray* rays, int count, bool* occluded) const;
    static constexpr int kCoherentBatch = 64;  // rays per stream call (an 8×8 tile)

    const AccelOptions& options() const { return m_options; }
    // Bytes Embree holds for this scene (BVH and geometry buffers), from its memory monitor.
    size_t embree_bytes() const { return static_cast<size_t>(m_embree_bytes.load()); }
    RTCScene rtc_scene() const { return m_rtc_scene; }  // for raw-Embree baselines
    size_t primitive_count() const { return m_primitive_count; }

private:
    enum class GeometryKind : uint8_t { UserSpheres, PointSpheres, SphereMesh, Cones, Mesh };
    struct GeometryRef {
        GeometryKind kind;
        uint32_t index;  // mesh index for Mesh; unused otherwise
    };

    void attach(RTCGeometry geometry, GeometryKind kind, uint32_t index);
    void add_sphere_geometry();
    // Nearest sphere in (tnear, tfar) by testing every sphere (SphereMethod::BruteForce).
    bool nearest_sphere_brute_force(const Ray& ray, float tfar, uint32_t& index, float& t) const;
    bool occluded_by_brute_force_spheres(const Ray& ray) const;
    bool finish_hit(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& hit) const;
    void fill_sphere_hit(const Ray& ray, float t, uint32_t sphere, SurfaceHit& hit) const;

    const Scene& m_scene;
    AccelOptions m_options;
    RTCDevice m_device = nullptr;
    RTCScene m_rtc_scene = nullptr;
    std::unique_ptr<AccelUserData> m_user_data;
    std::vector<GeometryRef> m_geometries;  // indexed by Embree geomID
    size_t m_primitive_count = 0;
    std::atomic<long long> m_embree_bytes{0};
    uint32_t m_triangles_per_sphere = 0;  // SphereMesh
    std::vector<Vec3> m_icosphere_normals;
    std::vector<std::array<uint32_t, 3>> m_icosphere_triangles;
};

}  // namespace rayo
