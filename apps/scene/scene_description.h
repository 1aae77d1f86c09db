#pragma once
// Everything a scene file says: geometry and camera (core), materials and lights (shading), and
// the render settings it asks for (command-line flags override them).
#include <optional>
#include <string>
#include <vector>

#include "core/adaptive_aa.h"
#include "core/scene.h"
#include "core/shape_method.h"
#include "core/sphere_method.h"
#include "core/tile_grid.h"
#include "shading/radiosity.h"
#include "shading/shading_scene.h"
#include "shading/whitted.h"

namespace rayo {

// Global illumination besides Whitted's ray tree: none, or a radiosity pre-pass whose solution
// the diffuse surfaces show (docs/radiosity.md).
enum class GlobalIllumination { None, Radiosity };

struct RenderSettings {
    int spp = 1;
    int tile_size = kDefaultTileSize;  // core/tile_grid.h
    SphereMath sphere_math = SphereMath::Stable;
    SphereRepresentation spheres{SphereMethod::Auto};  // --sphere-method; auto by default
    float max_error_px = 0.5f;                         // auto's error budget, in pixels
    // --shape-method: the method of every object with a mesh form, over the file's "method"s
    // (apps/scene/shape_method_choice.h); none: each object's own, analytic by default.
    std::optional<ShapeMethod> shape_method;
    bool coherent = true;  // tiles' camera and shadow rays as Embree streams (--single-rays: no)
    AntiAliasing aa = AntiAliasing::Stratified;  // "aa": stratified spp, or adaptive
    AdaptiveSettings adaptive;                   // "aa_threshold", "aa_depth"
    WhittedSettings whitted;
    GlobalIllumination gi = GlobalIllumination::None;  // "gi", --gi
    RadiositySettings radiosity;                       // the top-level "radiosity" object
    bool gi_view_patches = false;                      // --gi-view patches: flat patches
};

struct SceneDescription {
    std::string source;  // file path, or "<default>" for the built-in scene
    Scene scene;
    ShadingScene shading;
    RenderSettings settings;
    // Input that was dropped rather than refused (e.g. zero-area patches of a tessellation),
    // each "where: what"; the CLI prints them. skipped_triangles counts the triangles they held.
    std::vector<std::string> warnings;
    size_t skipped_triangles = 0;
    // The "method" of top-level objects that name one (objects without stay analytic).
    std::vector<ShapeMethodRequest> shape_methods;
};

}  // namespace rayo
