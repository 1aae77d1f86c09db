#pragma once
// The Embree acceleration structure: one committed RTCScene per render. Each registered shape
// type (core/shapes/registry.h) becomes one geometry in the representation make_binding picks
// (core/user_geometry.h): Embree user geometry running rayo's own intersection code, or for
// spheres the representation of AccelOptions::spheres (Embree points, icosphere triangles, one
// brute-force primitive; core/sphere_method.h). The meshes are Embree triangles (the mesh forms
// of shapes traced as meshes among them, apps/scene/shape_method_choice.h); height fields of the
// `dda` method and surface-mode voxel grids are user geometry walking their grid; composite-mode
// voxel grids are not in Embree (volumes(), composited by the integrator); each instanced group
// is a scene of its own built once, placed by Embree instance geometries
// (core/instance_binding.h). Follows the Embree 3 call order: device (one per process,
// core/embree_device.h) -> scene -> geometries -> commit, then trace.
#include <embree3/rtcore.h>

#include <memory>
#include <vector>

#include "core/accel_options.h"
#include "core/geometry_binding.h"
#include "core/instance_binding.h"
#include "core/ray.h"
#include "core/scene.h"
#include "core/surface_hit.h"

namespace rayo {

class Accel {
  public:
    Accel(const Scene& scene, const AccelOptions& options = {});
    ~Accel();
    Accel(const Accel&) = delete;
    Accel& operator=(const Accel&) = delete;

    bool intersect(const Ray& ray, SurfaceHit& hit) const;
    // True when anything lies on the ray within (tnear, tfar).
    bool occluded(const Ray& ray) const;

    // Batches go through Embree ray streams (rtcIntersect1M/rtcOccluded1M), kCoherentBatch rays
    // per call. Coherent (a tile's camera rays, their shadow rays toward one light): the
    // COHERENT context flag, Embree's packet-stream traversal. Incoherent (the rays spawned at
    // secondary hits): the INCOHERENT flag, occlusion rays sorted by direction octant, closest-hit
    // rays traced as packets. Ray by ray the results equal intersect()/occluded()
    // (tests/core/accel_test.cpp), except which of two coplanar overlapping triangles a
    // closest-hit query reports, which depends on the traversal order.
    enum class Coherence { Coherent, Incoherent };
    void intersect_coherent(const Ray* rays, int count, SurfaceHit* hits, bool* found,
                            Coherence coherence = Coherence::Coherent) const;
    void occluded_coherent(const Ray* rays, int count, bool* occluded,
                           Coherence coherence = Coherence::Coherent) const;
    static constexpr int kCoherentBatch = 64;  // rays per stream call (an 8×8 tile)

    // Fills hit.uv and hit.dpdu (the shape's parameterization) for a hit this accel returned.
    void parameterize(SurfaceHit& hit) const;

    const AccelOptions& options() const { return m_options; }
    // Bytes Embree allocated while building this scene (BVH and geometry buffers), from the
    // device's memory monitor; exact when scenes are built one at a time.
    size_t embree_bytes() const { return m_embree_bytes; }
    RTCScene rtc_scene() const { return m_rtc_scene; }  // for raw-Embree baselines
    // Primitives in the scene, each instance counting its group's (the instanced total), and
    // primitives stored (each instanced group once); the count of instances.
    size_t primitive_count() const { return m_primitive_count; }
    size_t stored_primitive_count() const { return m_stored_primitive_count; }
    size_t instance_count() const { return m_instance_count; }
    // Meshes with holes (AccelOptions::cutouts): those with the cutout filters, each instanced
    // group's once.
    size_t cutout_mesh_count() const { return m_cutout_mesh_count; }
    // The composite-mode voxel grids (docs/voxels.md): not in the Embree scene; the integrator
    // composites them along its rays (composite_volumes, core/shapes/voxel_grid.h).
    const std::vector<const VoxelGrid*>& volumes() const { return m_volumes; }

  private:
    bool finish_hit(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& hit) const;

    AccelOptions m_options;
    RTCScene m_rtc_scene = nullptr;
    std::vector<std::unique_ptr<GeometryBinding>> m_bindings;  // indexed by Embree geomID
    std::vector<const VoxelGrid*> m_volumes;                   // the scene's composite grids
    std::vector<GroupScene> m_groups;  // per Scene::groups entry; built when instanced
    size_t m_primitive_count = 0;
    size_t m_stored_primitive_count = 0;
    size_t m_instance_count = 0;
    size_t m_cutout_mesh_count = 0;
    size_t m_embree_bytes = 0;
};

}  // namespace rayo
