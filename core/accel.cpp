#include "core/accel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/shapes/icosphere.h"

namespace rayo {
namespace {

struct SphereGeometryData {
    const Sphere* spheres;
};

struct ConeGeometryData {
    const Cone* cones;
    const ConeFrame* frames;  // one per cone, prepared once
};

struct MeshGeometryData {
    const TriangleMesh* mesh;
};

}  // namespace

// The callbacks' user data, allocated once per Accel (Embree keeps raw pointers to it).
struct AccelUserData {
    SphereGeometryData spheres{};
    ConeGeometryData cones{};
    std::vector<ConeFrame> cone_frames;
    std::vector<MeshGeometryData> meshes;  // sized once: pointers into it stay valid
};

namespace {

Vec3 triangle_normal(const TriangleMesh& mesh, uint32_t prim) {
    const auto& tri = mesh.triangles[prim];
    const Vec3& p0 = mesh.positions[tri[0]];
    // Right-handed: counter-clockwise vertices seen from the side the normal points to.
    return glm::cross(mesh.positions[tri[1]] - p0, mesh.positions[tri[2]] - p0);
}

void fail_on_embree_error(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE) {
        throw std::runtime_error(std::string("Embree error ") + std::to_string(error) + " in " +
                                 what);
    }
}

// --- user geometry callbacks: written for any N (rtcIntersect1 calls them with N = 1, packets
// and streams with 4/8/16); per-lane data through the RTCRayN_/RTCHitN_ accessors (DESIGN.md).

void sphere_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* data = static_cast<const SphereGeometryData*>(args->geometryUserPtr);
    const Sphere& s = data->spheres[args->primID];
    RTCBounds* b = args->bounds_o;
    b->lower_x = s.center.x - s.radius;
    b->lower_y = s.center.y - s.radius;
    b->lower_z = s.center.z - s.radius;
    b->upper_x = s.center.x + s.radius;
    b->upper_y = s.center.y + s.radius;
    b->upper_z = s.center.z + s.radius;
}

template <typename RayN>
void read_ray(RayN* ray, unsigned n, unsigned i, Vec3& origin, Vec3& direction) {
    origin = Vec3(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i));
    direction = Vec3(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i));
}

void report_hit(RTCRayN* ray, RTCHitN* hit, unsigned n, unsigned i, float t, const Vec3& normal,
                unsigned geom_id, unsigned prim_id, const RTCIntersectContext* context) {
    RTCRayN_tfar(ray, n, i) = t;
    RTCHitN_Ng_x(hit, n, i) = normal.x;
    RTCHitN_Ng_y(hit, n, i) = normal.y;
    RTCHitN_Ng_z(hit, n, i) = normal.z;
    RTCHitN_u(hit, n, i) = 0.0f;
    RTCHitN_v(hit, n, i) = 0.0f;
    RTCHitN_primID(hit, n, i) = prim_id;
    RTCHitN_geomID(hit, n, i) = geom_id;
    RTCHitN_instID(hit, n, i, 0) = context->instID[0];
}

// Templated on the math so that each geometry's callback runs one form, inlined, without a
// per-ray switch.
template <SphereMath kMath>
void sphere_intersect(const RTCIntersectFunctionNArguments* args) {
    const auto* data = static_cast<const SphereGeometryData*>(args->geometryUserPtr);
    const Sphere& s = data->spheres[args->primID];
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        Vec3 origin, direction;
        read_ray(ray, args->N, i, origin, direction);
        float t;
        bool far_root;
        if (intersect_sphere(kMath, origin, direction, s.center, s.radius,
                             RTCRayN_tnear(ray, args->N, i), RTCRayN_tfar(ray, args->N, i), t,
                             far_root)) {
            // Outward normal; the integrator tells inside from outside by its sign against
            // the ray (equivalent to seed 000's flip for far-root hits).
            report_hit(ray, hit, args->N, i, t, origin + t * direction - s.center, args->geomID,
                       args->primID, args->context);
        }
    }
}

template <SphereMath kMath>
void sphere_occluded(const RTCOccludedFunctionNArguments* args) {
    const auto* data = static_cast<const SphereGeometryData*>(args->geometryUserPtr);
    const Sphere& s = data->spheres[args->primID];
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        Vec3 origin, direction;
        read_ray(args->ray, args->N, i, origin, direction);
        float t;
        bool far_root;
        if (intersect_sphere(kMath, origin, direction, s.center, s.radius,
                             RTCRayN_tnear(args->ray, args->N, i),
                             RTCRayN_tfar(args->ray, args->N, i), t, far_root)) {
            RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();
        }
    }
}

void cone_bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* data = static_cast<const ConeGeometryData*>(args->geometryUserPtr);
    Vec3 lower, upper;
    cone_bounds(data->cones[args->primID], lower, upper);
    RTCBounds* b = args->bounds_o;
    b->lower_x = lower.x;
    b->lower_y = lower.y;
    b->lower_z = lower.z;
    b->upper_x = upper.x;
    b->upper_y = upper.y;
    b->upper_z = upper.z;
}

void cone_intersect(const RTCIntersectFunctionNArguments* args) {
    const auto* data = static_cast<const ConeGeometryData*>(args->geometryUserPtr);
    const ConeFrame& c = data->frames[args->primID];
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        Vec3 origin, direction, normal;
        read_ray(ray, args->N, i, origin, direction);
        float t;
        if (intersect_cone(c, origin, direction, RTCRayN_tnear(ray, args->N, i),
                           RTCRayN_tfar(ray, args->N, i), t, normal)) {
            report_hit(ray, hit, args->N, i, t, normal, args->geomID, args->primID,
                       args->context);
        }
    }
}

void cone_occluded(const RTCOccludedFunctionNArguments* args) {
    const auto* data = static_cast<const ConeGeometryData*>(args->geometryUserPtr);
    const ConeFrame& c = data->frames[args->primID];
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        Vec3 origin, direction, normal;
        read_ray(args->ray, args->N, i, origin, direction);
        float t;
        if (intersect_cone(c, origin, direction, RTCRayN_tnear(args->ray, args->N, i),
                           RTCRayN_tfar(args->ray, args->N, i), t, normal)) {
            RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();
        }
    }
}

// One-sided meshes: reject hits on the back of a triangle (NFF polygons, DESIGN.md).
void cull_back_faces(const RTCFilterFunctionNArguments* args) {
    const auto* data = static_cast<const MeshGeometryData*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const Vec3 direction(RTCRayN_dir_x(args->ray, args->N, i),
                             RTCRayN_dir_y(args->ray, args->N, i),
                             RTCRayN_dir_z(args->ray, args->N, i));
        const uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
        if (glm::dot(triangle_normal(*data->mesh, prim), direction) >= 0.0f) args->valid[i] = 0;
    }
}

RTCRay make_rtc_ray(const Ray& ray) {
    RTCRay r;
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x;
    r.dir_y = ray.direction.y;
    r.dir_z = ray.direction.z;
    r.tnear = ray.tnear;
    r.tfar = ray.tfar;
    r.time = 0.0f;
    r.mask = 0xFFFFFFFFu;  // Debian's Embree has ray masks on: mask 0 would hit nothing
    r.id = 0;
    r.flags = 0;
    return r;
}

RTCRayHit make_rtc_rayhit(const Ray& ray) {
    RTCRayHit rayhit;
    rayhit.ray = make_rtc_ray(ray);
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rayhit;
}

}  // namespace

Accel::Accel(const Scene& scene, const AccelOptions& options)
    : m_scene(scene), m_options(options) {
    if (options.spheres.method == SphereMethod::Auto) {
        throw std::logic_error("Accel: the auto sphere method must be resolved by the caller");
    }
    m_device = rtcNewDevice(nullptr);
    if (!m_device) throw std::runtime_error("Embree: cannot create a device");
    rtcSetDeviceMemoryMonitorFunction(
        m_device,
        [](void* user, ssize_t bytes, bool /*post*/) {
            static_cast<std::atomic<long long>*>(user)->fetch_add(bytes);
            return true;  // never refuse an allocation
        },
        &m_embree_bytes);
    m_rtc_scene = rtcNewScene(m_device);
    rtcSetSceneFlags(m_rtc_scene, options.robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
    rtcSetSceneBuildQuality(m_rtc_scene, RTC_BUILD_QUALITY_HIGH);
    m_user_data = std::make_unique<AccelUserData>();
    m_user_data->meshes.resize(scene.meshes.size());

    if (!scene.spheres.empty()) add_sphere_geometry();
    if (!scene.cones.empty()) {
        for (const Cone& c : scene.cones) m_user_data->cone_frames.push_back(make_cone_frame(c));
        ConeGeometryData* data = &m_user_data->cones;
        data->cones = scene.cones.data();
        data->frames = m_user_data->cone_frames.data();
        RTCGeometry g = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(scene.cones.size()));
        rtcSetGeometryUserData(g, data);
        rtcSetGeometryBoundsFunction(g, cone_bounds_callback, nullptr);
        rtcSetGeometryIntersectFunction(g, cone_intersect);
        rtcSetGeometryOccludedFunction(g, cone_occluded);
        attach(g, GeometryKind::Cones, 0);
        m_primitive_count += scene.cones.size();
    }
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const TriangleMesh& mesh = scene.meshes[m];
        if (mesh.triangles.empty()) continue;
        RTCGeometry g = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
        // Copies into Embree-owned buffers: Embree reads vertices as 16 bytes, so a shared
        // std::vector<Vec3> would be over-read at its end.
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(float) * 3,
            mesh.positions.size()));
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            vertices[3 * v + 0] = mesh.positions[v].x;
            vertices[3 * v + 1] = mesh.positions[v].y;
            vertices[3 * v + 2] = mesh.positions[v].z;
        }
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(unsigned) * 3,
            mesh.triangles.size()));
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            indices[3 * t + 0] = mesh.triangles[t][0];
            indices[3 * t + 1] = mesh.triangles[t][1];
            indices[3 * t + 2] = mesh.triangles[t][2];
        }
        if (mesh.one_sided) {
            m_user_data->meshes[m].mesh = &mesh;
            rtcSetGeometryUserData(g, &m_user_data->meshes[m]);
            rtcSetGeometryIntersectFilterFunction(g, cull_back_faces);
            rtcSetGeometryOccludedFilterFunction(g, cull_back_faces);
        }
        attach(g, GeometryKind::Mesh, static_cast<uint32_t>(m));
        m_primitive_count += mesh.triangles.size();
    }
    rtcCommitScene(m_rtc_scene);
    fail_on_embree_error(m_device, "scene commit");
}

void Accel::attach(RTCGeometry geometry, GeometryKind kind, uint32_t index) {
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(m_rtc_scene, geometry);
    rtcReleaseGeometry(geometry);
    if (id >= m_geometries.size()) m_geometries.resize(id + 1);
    m_geometries[id] = GeometryRef{kind, index};
}

void Accel::add_sphere_geometry() {
    const std::vector<Sphere>& spheres = m_scene.spheres;
    switch (m_options.spheres.method) {
        case SphereMethod::BruteForce:
            // No BVH: intersect() and occluded() test every sphere themselves.
            m_primitive_count += spheres.size();
            return;
        case SphereMethod::User: {
            SphereGeometryData* data = &m_user_data->spheres;
            data->spheres = spheres.data();
            RTCGeometry g = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_USER);
            rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(spheres.size()));
            rtcSetGeometryUserData(g, data);  // Embree 3 ignores the bounds function's pointer
            rtcSetGeometryBoundsFunction(g, sphere_bounds, nullptr);
            switch (m_options.sphere_math) {
                case SphereMath::Seed:
                    rtcSetGeometryIntersectFunction(g, sphere_intersect<SphereMath::Seed>);
                    rtcSetGeometryOccludedFunction(g, sphere_occluded<SphereMath::Seed>);
                    break;
                case SphereMath::Stable:
                    rtcSetGeometryIntersectFunction(g, sphere_intersect<SphereMath::Stable>);
                    rtcSetGeometryOccludedFunction(g, sphere_occluded<SphereMath::Stable>);
                    break;
                case SphereMath::Double:
                    rtcSetGeometryIntersectFunction(g, sphere_intersect<SphereMath::Double>);
                    rtcSetGeometryOccludedFunction(g, sphere_occluded<SphereMath::Double>);
                    break;
            }
            attach(g, GeometryKind::UserSpheres, 0);
            break;
        }
        case SphereMethod::EmbreePoint: {
            RTCGeometry g = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            auto* points = static_cast<float*>(
                rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                        4 * sizeof(float), spheres.size()));
            for (size_t i = 0; i < spheres.size(); ++i) {
                points[4 * i + 0] = spheres[i].center.x;
                points[4 * i + 1] = spheres[i].center.y;
                points[4 * i + 2] = spheres[i].center.z;
                points[4 * i + 3] = spheres[i].radius;
            }
            attach(g, GeometryKind::PointSpheres, 0);
            break;
        }
        case SphereMethod::Mesh: {
            Icosphere unit = make_icosphere(m_options.spheres.mesh_level);
            m_triangles_per_sphere = static_cast<uint32_t>(unit.triangles.size());
            const size_t vertex_count = unit.positions.size();
            RTCGeometry g = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* vertices = static_cast<float*>(
                rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                        3 * sizeof(float), spheres.size() * vertex_count));
            auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
                g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                spheres.size() * unit.triangles.size()));
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
            m_icosphere_normals = std::move(unit.positions);
            m_icosphere_triangles = std::move(unit.triangles);
            attach(g, GeometryKind::SphereMesh, 0);
            m_primitive_count += spheres.size() * m_triangles_per_sphere;
            return;
        }
        case SphereMethod::Auto: break;
    }
    m_primitive_count += spheres.size();
}

Accel::~Accel() {
    if (m_rtc_scene) rtcReleaseScene(m_rtc_scene);
    if (m_device) rtcReleaseDevice(m_device);
}

bool Accel::nearest_sphere_brute_force(const Ray& ray, float tfar, uint32_t& index,
                                       float& t) const {
    bool found = false;
    const auto count = static_cast<uint32_t>(m_scene.spheres.size());
    for (uint32_t i = 0; i < count; ++i) {
        const Sphere& s = m_scene.spheres[i];
        float candidate;
        bool far_root;
        if (intersect_sphere(m_options.sphere_math, ray.origin, ray.direction, s.center, s.radius,
                             ray.tnear, tfar, candidate, far_root)) {
            tfar = candidate;
            t = candidate;
            index = i;
            found = true;
        }
    }
    return found;
}

void Accel::fill_sphere_hit(const Ray& ray, float t, uint32_t sphere, SurfaceHit& hit) const {
    const Sphere& s = m_scene.spheres[sphere];
    // Re-project the hit point onto the sphere (DESIGN.md "Numerics"). A sphere below one ulp
    // of its position can put the hit on its centre in float: face the ray instead of dividing
    // by zero (a NaN origin would reach Embree; docs/stability.md, breaking points).
    const Vec3 offset = ray.at(t) - s.center;
    const float length_squared = glm::dot(offset, offset);
    const Vec3 outward =
        length_squared > 0.0f ? offset * glm::inversesqrt(length_squared) : -ray.direction;
    hit.t = t;
    hit.kind = PrimitiveKind::Sphere;
    hit.position = s.center + s.radius * outward;
    hit.geometric_normal = outward;
    hit.shading_normal = outward;
    hit.object_size = s.radius;
    hit.material = s.material;
    hit.primitive = sphere;
}

bool Accel::intersect(const Ray& ray, SurfaceHit& hit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayhit = make_rtc_rayhit(ray);
    rtcIntersect1(m_rtc_scene, &context, &rayhit);
    return finish_hit(ray, rayhit, hit);
}

void Accel::intersect_coherent(const Ray* rays, int count, SurfaceHit* hits, bool* found) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    RTCRayHit batch[kCoherentBatch];
    for (int first = 0; first < count; first += kCoherentBatch) {
        const int n = std::min(kCoherentBatch, count - first);
        for (int i = 0; i < n; ++i) batch[i] = make_rtc_rayhit(rays[first + i]);
        rtcIntersect1M(m_rtc_scene, &context, batch, static_cast<unsigned>(n), sizeof(RTCRayHit));
        for (int i = 0; i < n; ++i) {
            found[first + i] = finish_hit(rays[first + i], batch[i], hits[first + i]);
        }
    }
}

void Accel::occluded_coherent(const Ray* rays, int count, bool* occluded) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    RTCRay batch[kCoherentBatch];
    for (int first = 0; first < count; first += kCoherentBatch) {
        const int n = std::min(kCoherentBatch, count - first);
        for (int i = 0; i < n; ++i) batch[i] = make_rtc_ray(rays[first + i]);
        rtcOccluded1M(m_rtc_scene, &context, batch, static_cast<unsigned>(n), sizeof(RTCRay));
        for (int i = 0; i < n; ++i) {
            occluded[first + i] =
                batch[i].tfar < 0.0f || occluded_by_brute_force_spheres(rays[first + i]);
        }
    }
}

bool Accel::occluded_by_brute_force_spheres(const Ray& ray) const {
    if (m_options.spheres.method != SphereMethod::BruteForce || m_scene.spheres.empty()) {
        return false;
    }
    uint32_t sphere;
    float t;
    return nearest_sphere_brute_force(ray, ray.tfar, sphere, t);
}

// The hit record of an Embree result, with the brute-force spheres (if any) tested up to it.
bool Accel::finish_hit(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& hit) const {
    const bool embree_hit = rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    if (m_options.spheres.method == SphereMethod::BruteForce && !m_scene.spheres.empty()) {
        uint32_t sphere;
        float t;
        if (nearest_sphere_brute_force(ray, embree_hit ? rayhit.ray.tfar : ray.tfar, sphere, t)) {
            fill_sphere_hit(ray, t, sphere, hit);
            return true;
        }
    }
    if (!embree_hit) return false;

    const float t = rayhit.ray.tfar;
    const uint32_t prim = rayhit.hit.primID;
    const GeometryRef& ref = m_geometries[rayhit.hit.geomID];
    hit.t = t;
    switch (ref.kind) {
        case GeometryKind::UserSpheres:
        case GeometryKind::PointSpheres:
            fill_sphere_hit(ray, t, prim, hit);
            break;
        case GeometryKind::SphereMesh: {
            // The tessellation is the surface: no re-projection, so its silhouette and facet
            // error show in the image, which is what the comparison measures.
            const uint32_t sphere = prim / m_triangles_per_sphere;
            const auto& tri = m_icosphere_triangles[prim % m_triangles_per_sphere];
            const Vec3& n0 = m_icosphere_normals[tri[0]];
            const Vec3 flat = glm::normalize(
                glm::cross(m_icosphere_normals[tri[1]] - n0, m_icosphere_normals[tri[2]] - n0));
            hit.kind = PrimitiveKind::Sphere;
            hit.position = ray.at(t);
            hit.geometric_normal = flat;
            hit.shading_normal = flat;
            if (m_options.spheres.mesh_smooth) {
                const float u = rayhit.hit.u, v = rayhit.hit.v;
                hit.shading_normal = glm::normalize((1.0f - u - v) * n0 +
                                                    u * m_icosphere_normals[tri[1]] +
                                                    v * m_icosphere_normals[tri[2]]);
            }
            hit.object_size = m_scene.spheres[sphere].radius;
            hit.material = m_scene.spheres[sphere].material;
            hit.primitive = sphere;
            break;
        }
        case GeometryKind::Cones: {
            const Cone& c = m_scene.cones[prim];
            hit.kind = PrimitiveKind::Cone;
            hit.position = ray.at(t);
            hit.geometric_normal = glm::normalize(
                Vec3(rayhit.hit.Ng_x, rayhit.hit.Ng_y, rayhit.hit.Ng_z));
            hit.shading_normal = hit.geometric_normal;
            hit.object_size = glm::max(glm::length(c.apex - c.base),
                                       glm::max(c.base_radius, c.apex_radius));
            hit.material = c.material;
            hit.primitive = prim;
            break;
        }
        case GeometryKind::Mesh: {
            const TriangleMesh& mesh = m_scene.meshes[ref.index];
            const auto& tri = mesh.triangles[prim];
            const Vec3 ng = triangle_normal(mesh, prim);
            hit.kind = PrimitiveKind::Triangle;
            hit.position = ray.at(t);
            hit.geometric_normal = glm::normalize(ng);
            hit.shading_normal = hit.geometric_normal;
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
                    hit.shading_normal =
                        glm::dot(unit, hit.geometric_normal) >= 0.0f ? unit : -unit;
                }
            }
            const Vec3& p0 = mesh.positions[tri[0]];
            hit.object_size = glm::max(glm::length(mesh.positions[tri[1]] - p0),
                                       glm::length(mesh.positions[tri[2]] - p0));
            hit.material = mesh.materials[prim];
            hit.primitive = prim;
            hit.mesh = ref.index;
            break;
        }
    }
    return true;
}

bool Accel::occluded(const Ray& ray) const {
    if (occluded_by_brute_force_spheres(ray)) return true;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r = make_rtc_ray(ray);
    rtcOccluded1(m_rtc_scene, &context, &r);
    return r.tfar < 0.0f;
}

}  // namespace rayo
