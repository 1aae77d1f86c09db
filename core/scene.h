#pragma once
// The geometric scene: camera, the analytic shapes (one vector per registered type,
// core/shapes/registry.h) and triangle meshes, with material ids. Materials and lights live in
// shading/ (core knows nothing of shading); the loaders fill both. Height fields of the `dda`
// method are kept as grids; the `mesh` method's are among the meshes. Voxel grids are kept as
// grids.
#include <string>
#include <utility>
#include <vector>

#include "core/camera.h"
#include "core/instance.h"
#include "core/scene_limits.h"
#include "core/shapes/height_field.h"
#include "core/shapes/mesh.h"
#include "core/shapes/registry.h"
#include "core/shapes/voxel_grid.h"

namespace rayo {

// SurfaceHit::shape of a triangle hit (the analytic shapes are 0 .. kCount − 1).
constexpr uint32_t kTriangleShape = AnalyticShapes::kCount;
// SurfaceHit::shape of a hit on a height field traced by its grid traversal (SurfaceHit::mesh is
// the field's index in Scene::heightfields; the `mesh` method's hits are triangle hits).
constexpr uint32_t kHeightFieldShape = kTriangleShape + 1;
// SurfaceHit::shape of a hit on a surface-mode voxel grid (SurfaceHit::mesh is its index in
// Scene::voxels).
constexpr uint32_t kVoxelShape = kTriangleShape + 2;

struct Scene {
    CameraDesc camera;
    Shapes shapes;
    std::vector<TriangleMesh> meshes;
    std::vector<HeightField> heightfields;  // traced by grid traversal (docs/heightfields.md)
    // Voxel grids (docs/voxels.md): surface-mode grids are Embree user geometry, composite-mode
    // grids are composited along the rays by the integrator.
    std::vector<VoxelGrid> voxels;
    // Named groups of objects and their placements (core/instance.h); empty for most scenes.
    std::vector<ShapeGroup> groups;
    std::vector<Instance> instances;

    // Analytic shapes and triangles placed through instances (each instance counts its group).
    size_t instanced_object_count() const {
        size_t n = 0;
        for (const Instance& i : instances) n += groups[i.group].object_count();
        return n;
    }
    size_t triangle_count() const {
        size_t n = 0;
        for (const auto& m : meshes) n += m.triangle_count();
        return n;
    }
    // (plural name, count) of each registered shape type, in registry order: "spheres", "boxes".
    std::vector<std::pair<std::string, size_t>> shape_counts() const {
        std::vector<std::pair<std::string, size_t>> counts;
        shapes.for_each([&](const auto& v) {
            const std::string name = ShapeOf<decltype(v)>::kName;
            counts.emplace_back(name + (name.back() == 'x' ? "es" : "s"), v.size());
        });
        return counts;
    }
};

}  // namespace rayo
