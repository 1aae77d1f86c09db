#include "core/accel.h"

#include <algorithm>
#include <stdexcept>

#include "core/embree_device.h"
#include "core/embree_ray.h"
#include "core/instance_binding.h"
#include "core/shapes/height_field_geometry.h"
#include "core/shapes/mesh_geometry.h"
#include "core/shapes/sphere_geometry.h"
#include "core/user_geometry.h"

namespace rayo {
namespace {

RTCScene new_rtc_scene(const AccelOptions& options) {
    RTCScene scene = rtcNewScene(embree_device());
    rtcSetSceneFlags(scene, options.robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    return scene;
}

// Commits the binding's geometry, attaches it to `scene` and keeps the binding at its geometry
// id; returns its primitive count.
size_t attach(RTCScene scene, std::vector<std::unique_ptr<GeometryBinding>>& bindings,
              std::unique_ptr<GeometryBinding> binding) {
    RTCGeometry geometry = binding->geometry();
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    fail_on_embree_error("geometry set-up");
    const size_t primitives = binding->primitive_count();
    if (id >= bindings.size()) bindings.resize(id + 1);
    bindings[id] = std::move(binding);
    return primitives;
}

// Every registered shape type in registry order (make_binding picks its representation), then
// the meshes: of the scene itself or of a group (core/instance.h). Meshes with a cut material
// (core/cutout.h) get the cutout filters and are counted in `cut_meshes`.
template <typename Objects>
size_t attach_objects(RTCScene scene, std::vector<std::unique_ptr<GeometryBinding>>& bindings,
                      const Objects& objects, const AccelOptions& options, size_t& cut_meshes) {
    size_t primitives = 0;
    objects.shapes.for_each([&](const auto& shapes) {
        using S = ShapeOf<decltype(shapes)>;
        if (!shapes.empty()) {
            primitives +=
                attach(scene, bindings, make_binding(shapes, Shapes::index_of<S>(), options));
        }
    });
    for (size_t m = 0; m < objects.meshes.size(); ++m) {
        const TriangleMesh& mesh = objects.meshes[m];
        if (mesh.triangles.empty()) continue;
        const bool cut = options.cutouts && mesh_has_cutout(mesh, *options.cutouts);
        cut_meshes += cut ? 1 : 0;
        primitives += attach(scene, bindings,
                             make_mesh_binding(mesh, static_cast<uint32_t>(m), kTriangleShape,
                                               cut ? options.cutouts : nullptr));
    }
    return primitives;
}

}  // namespace

Accel::Accel(const Scene& scene, const AccelOptions& options) : m_options(options) {
    if (options.spheres.method == SphereMethod::Auto) {
        throw std::logic_error("Accel: the auto sphere method must be resolved by the caller");
    }
    const long long bytes_before = embree_bytes_in_use();
    m_rtc_scene = new_rtc_scene(options);
    m_primitive_count =
        attach_objects(m_rtc_scene, m_bindings, scene, options, m_cutout_mesh_count);
    // Height fields traced by grid traversal (docs/heightfields.md): one primitive each here,
    // whatever their cell count.
    for (size_t f = 0; f < scene.heightfields.size(); ++f) {
        m_primitive_count +=
            attach(m_rtc_scene, m_bindings,
                   make_height_field_binding(scene.heightfields[f], static_cast<uint32_t>(f),
                                             kHeightFieldShape));
    }
    // Voxel grids (docs/voxels.md): a surface-mode grid is one user primitive walking its
    // dual grid; composite-mode grids are not surfaces, the integrator composites them.
    for (size_t v = 0; v < scene.voxels.size(); ++v) {
        const VoxelGrid& grid = scene.voxels[v];
        if (grid.mode == VoxelMode::Composite) {
            m_volumes.push_back(&grid);
            continue;
        }
        m_primitive_count += attach(m_rtc_scene, m_bindings,
                                    std::make_unique<ObjectBinding<VoxelGrid>>(
                                        grid, static_cast<uint32_t>(v), kVoxelShape, 1));
    }
    m_stored_primitive_count = m_primitive_count;
    // Instancing: each instanced group's scene is built once; each instance is one Embree
    // instance geometry of the top scene pointing at it.
    m_groups.resize(scene.groups.size());
    for (const Instance& instance : scene.instances) {
        GroupScene& group = m_groups.at(instance.group);
        if (group.scene) continue;
        group.scene = new_rtc_scene(options);
        group.primitive_count =
            attach_objects(group.scene, group.bindings, scene.groups[instance.group], options,
                           m_cutout_mesh_count);
        rtcCommitScene(group.scene);
        fail_on_embree_error("group scene commit");
        m_stored_primitive_count += group.primitive_count;
    }
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        m_primitive_count +=
            attach(m_rtc_scene, m_bindings,
                   std::make_unique<InstanceBinding>(m_groups[instance.group], instance,
                                                     static_cast<uint32_t>(i)));
    }
    m_instance_count = scene.instances.size();
    rtcCommitScene(m_rtc_scene);
    fail_on_embree_error("scene commit");
    m_embree_bytes = static_cast<size_t>(std::max(0LL, embree_bytes_in_use() - bytes_before));
}

Accel::~Accel() {
    if (m_rtc_scene) rtcReleaseScene(m_rtc_scene);
    for (GroupScene& group : m_groups) {
        if (group.scene) rtcReleaseScene(group.scene);
    }
}

bool Accel::intersect(const Ray& ray, SurfaceHit& hit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayhit = make_rtc_rayhit(ray);
    rtcIntersect1(m_rtc_scene, &context, &rayhit);
    return finish_hit(ray, rayhit, hit);
}

void Accel::intersect_coherent(const Ray* rays, int count, SurfaceHit* hits, bool* found,
                               Coherence coherence) const {
    RTCIntersectContext context = stream_context(coherence);
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

void Accel::occluded_coherent(const Ray* rays, int count, bool* occluded,
                              Coherence coherence) const {
    RTCIntersectContext context = stream_context(coherence);
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
    // Through an instance, geomID names the geometry within the group and instID[0] the
    // instance: its binding carries the group's hit to world space (core/instance_binding.h).
    const unsigned instance = rayhit.hit.instID[0];
    const unsigned geometry = instance != RTC_INVALID_GEOMETRY_ID ? instance : rayhit.hit.geomID;
    // A record the caller reuses (the path integrator's vertex, a stream's batch) starts fresh:
    // a binding fills only what its shape has (a sphere no vertex colour or tangent).
    hit = SurfaceHit{};
    m_bindings[geometry]->surface(ray, rayhit, hit);
    hit.geometry = geometry;
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
