#pragma once
// Shape methods: each top-level object with a mesh form (core/shapes/mesh_form.h; every shape
// with pieces but the sphere, which has `--sphere-method`) is traced analytically or as Embree
// triangles within the pixel error budget, as its "method" (or `--shape-method`) says; `auto`
// picks per object from the budget and the measured costs (docs/shape-methods.md).
#include <optional>
#include <string>
#include <vector>

#include "apps/scene/scene_description.h"
#include "core/camera.h"

namespace rayo {

// What one object ran as, and why.
struct ShapeMethodChoice {
    std::string type;  // its scene-file name ("cylinder")
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

// The measurements behind auto (docs/shape-methods.md, `rayo bench accuracy --only shapes`):
// Embree bytes per triangle of a mesh form (vertex, normal and index buffers and the BVH), and
// auto's limits: a mesh form is taken when it has at most kAutoMeshMaxTriangles triangles (below
// that, triangles traced faster than the analytic code in every shape's study) and at most
// kAutoMeshMaxBytes.
constexpr size_t kMeshBytesPerTriangle = 160;
constexpr size_t kAutoMeshMaxTriangles = 2048;
constexpr size_t kAutoMeshMaxBytes = size_t(1) << 20;

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
