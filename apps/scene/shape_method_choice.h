#pragma once
// Shape methods: each top-level object with a mesh form (core/shapes/mesh_form.h; every shape
// with pieces, and blobs, but the sphere, which has `--sphere-method`) is traced analytically or as
// Embree triangles within the pixel error budget, as its "method" (or `--shape-method`) says;
// `auto` picks per object from the budget and the measured costs (docs/shape-methods.md).
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "apps/scene/scene_description.h"
#include "core/camera.h"

namespace rayo {

// What one object ran as, and why.
struct ShapeMethodChoice {
    std::string type;    // its scene-file name ("cylinder")
    uint32_t index = 0;  // among Scene::shapes of its type
    ShapeMethod requested = ShapeMethod::Analytic;
    ShapeMethod chosen = ShapeMethod::Analytic;
    // The mesh form within the budget (mesh, or what auto weighed): its triangles, estimated
    // bytes (kMeshBytesPerTriangle) and chord error in pixels at the object's nearest point.
    size_t triangles = 0;
    size_t bytes = 0;
    float chord_px = 0.0f;
    std::string reason;
};

struct ShapeChoices {
    // Every object whose method was not plain analytic by default (requested mesh or auto, or
    // analytic by a "method"/--shape-method); objects in groups stay analytic and are not listed.
    std::vector<ShapeMethodChoice> objects;
    // The scene with the meshed objects as triangle meshes (appended to Scene::meshes); empty
    // when every object stays analytic, so that the scene is traced as loaded.
    std::optional<Scene> scene;
    const Scene& traced(const Scene& loaded) const { return scene ? *scene : loaded; }
};

// The measurements behind auto (docs/shape-methods.md, `rayo bench accuracy --only shapes`, one
// thread): the clipped-quadric forms (ellipsoid, cylinder, paraboloid, hyperboloid: a general
// quadric clipped to a box, core/shapes/clipped_quadric.h) cost 34–42 ns per coherent camera ray
// analytically against 13–27 ns as meshes of up to 15,000 triangles, and single rays cost about
// the same both ways up to some 4,000 triangles; the cone's, disk's and box's own code (15–22 ns)
// is as fast as their meshes on camera rays and faster on single rays. So auto takes the mesh
// form of a clipped quadric when it has at most kAutoMeshMaxTriangles triangles, while the
// scene's mesh forms stay within kAutoMeshSceneBytes (objects met after that stay analytic), and
// keeps the other shapes analytic. Embree takes about kMeshBytesPerTriangle per triangle of a
// mesh form (82–120 measured, BVH and buffers) against 1152 bytes for an analytic object.
constexpr size_t kMeshBytesPerTriangle = 100;
constexpr size_t kAutoMeshMaxTriangles = 4096;
constexpr size_t kAutoMeshSceneBytes = size_t(64) << 20;

// Blobs (docs/csg-and-blobs.md, bench/blob_study.cpp, five elements, one thread): the
// interval-bounded search traces 1.5–2.2 Mrays/s; marching-tetrahedra meshes of 2,364 to 152,736
// triangles (16 to 128 cells across) trace 3.8 to 2.4 Mrays/s, 610,739 (256 cells) about as
// fast as the search, 2.4 M (512 cells) at 0.9. So auto takes a blob's mesh form when a lattice
// of at most kAutoBlobMeshMaxCells cells across reaches the budget, which keeps it under
// kAutoBlobMeshMaxTriangles (and within kAutoMeshSceneBytes with the scene's other meshes).
constexpr int kAutoBlobMeshMaxCells = 128;
constexpr size_t kAutoBlobMeshMaxTriangles = 160000;

// The most triangles auto takes for a shape's mesh form; 0: auto keeps it analytic.
template <typename S>
constexpr size_t auto_mesh_max_triangles() {
    if constexpr (std::is_same_v<S, Blob>) {
        return kAutoBlobMeshMaxTriangles;
    } else if constexpr (std::is_same_v<typename ShapeTraits<S>::Intersector, ClippedQuadric>) {
        return kAutoMeshMaxTriangles;
    } else {
        return 0;
    }
}

// Whether auto may take a shape's mesh form: the clipped quadrics and blobs (above).
template <typename S>
constexpr bool auto_may_mesh() {
    return auto_mesh_max_triangles<S>() > 0;
}

// The world-space chord error `max_error_px` allows at `distance` from the eye.
inline float chord_budget(float max_error_px, float pixel_angle, float distance) {
    return max_error_px * pixel_angle * distance;
}

ShapeChoices choose_shape_methods(const SceneDescription& description, const Camera& camera);

// For --stats: one line per shape type ("cylinder: 2 mesh (1204 triangles, 188 KB, <= 0.41 px),
// 1 analytic"), then one per object when there are at most kShapeMethodLinesPerObject.
constexpr size_t kShapeMethodLinesPerObject = 16;
std::vector<std::string> shape_method_lines(const std::vector<ShapeMethodChoice>& choices);

}  // namespace rayo
