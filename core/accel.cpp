#include "core/accel.h"

#include <algorithm>
#include <stdexcept>

#include "core/embree_device.h"
#include "core/shapes/height_field_geometry.h"
#include "core/shapes/mesh_geometry.h"
#include "core/shapes/sphere_geometry.h"
#include "core/user_geometry.h"

namespace rayo {
namespace {

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

Accel::Accel(const Scene& scene, const AccelOptions& options) : m_options(options) {
    if (options.spheres.method == SphereMethod::Auto) {
        throw std::logic_error("Accel: the auto sphere method must be resolved by the caller");
    }
    const long long bytes_before = embree_bytes_in_use();
    m_rtc_scene = rtcNewScene(embree_device());
    rtcSetSceneFlags(m_rtc_scene, options.robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
    rtcSetSceneBuildQuality(m_rtc_scene, RTC_BUILD_QUALITY_HIGH);
    // Every registered shape type, in registry order; make_binding picks its representation.
    scene.shapes.for_each([&](const auto& shapes) {
        using S = ShapeOf<decltype(shapes)>;
        if (!shapes.empty()) attach(make_binding(shapes, Shapes::index_of<S>(), options));
    });
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        if (scene.meshes[m].triangles.empty()) continue;
        attach(make_mesh_binding(scene.meshes[m], static_cast<uint32_t>(m), kTriangleShape));
    }
    for (size_t f = 0; f < scene.heightfields.size(); ++f) {
        attach(make_height_field_binding(scene.heightfields[f], static_cast<uint32_t>(f),
                                         kHeightFieldShape));
    }
    rtcCommitScene(m_rtc_scene);
    fail_on_embree_error("scene commit");
    m_embree_bytes = static_cast<size_t>(std::max(0LL, embree_bytes_in_use() - bytes_before));
}

void Accel::attach(std::unique_ptr<GeometryBinding> binding) {
    RTCGeometry geometry = binding->geometry();
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(m_rtc_scene, geometry);
    rtcReleaseGeometry(geometry);
    fail_on_embree_error("geometry set-up");
    m_primitive_count += binding->primitive_count();
    if (id >= m_bindings.size()) m_bindings.resize(id + 1);
    m_bindings[id] = std::move(binding);
}

Accel::~Accel() {
    if (m_rtc_scene) rtcReleaseScene(m_rtc_scene);
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
        for (int i = 0; i < n; ++i) occluded[first + i] = batch[i].tfar < 0.0f;
    }
}

bool Accel::finish_hit(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& hit) const {
    if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    m_bindings[rayhit.hit.geomID]->surface(ray, rayhit, hit);
    hit.geometry = rayhit.hit.geomID;
    return true;
}

void Accel::parameterize(SurfaceHit& hit) const {
    m_bindings.at(hit.geometry)->parameterize(hit);
}

bool Accel::occluded(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r = make_rtc_ray(ray);
    rtcOccluded1(m_rtc_scene, &context, &r);
    return r.tfar < 0.0f;
}

}  // namespace rayo
