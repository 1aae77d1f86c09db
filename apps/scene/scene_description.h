#pragma once
// Everything a scene file says: geometry and camera (core), materials and lights (shading), and
// the render settings it asks for (command-line flags override them).
#include <optional>
#include <string>
#include <vector>

#include "apps/scene/gltf_nodes.h"
#include "apps/scene/input_file.h"
#include "core/adaptive_aa.h"
#include "core/progressive_settings.h"
#include "core/scene.h"
#include "core/setting.h"
#include "core/shape_method.h"
#include "core/shapes/shape_fields.h"
#include "core/sphere_method.h"
#include "core/tile_grid.h"
#include "shading/integrators/integrator.h"
#include "shading/mip_pyramid.h"
#include "shading/radiosity.h"
#include "shading/shading_scene.h"

namespace rayo {

// Global illumination besides Whitted's ray tree: none, or a radiosity pre-pass whose solution
// the diffuse surfaces show (docs/radiosity.md).
enum class GlobalIllumination { None, Radiosity };

// The largest --spp / "spp": the stratified offsets come from a 32-bit hash; more gains nothing
// visible (docs/limits.md).
constexpr int kMaxSpp = 1 << 16;
static_assert(ProgressiveSettings{}.max_spp <= kMaxSpp, "a progressive render's default cap");

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
    AntiAliasing aa = AntiAliasing::Stratified;  // "aa": stratified spp, adaptive or corners
    AdaptiveSettings adaptive;                   // "aa_threshold", "aa_depth"
    // "render": {"integrator": {"type": ...}} and --integrator: the registered integrators
    // (shading/integrators/integrator.h), Whitted by default.
    IntegratorSettings integrator;
    GlobalIllumination gi = GlobalIllumination::None;  // "gi", --gi
    RadiositySettings radiosity;                       // the top-level "radiosity" object
    bool gi_view_patches = false;                      // --gi-view patches: flat patches
    // The image-texture cache's limit ("texture_cache_mb", --texture-cache): decoded tiles
    // held at once by the render's TextureSystem (shading/image_texture.h).
    float texture_cache_mb = kDefaultTextureCacheMB;
    // The image textures' filter within a MIP level ("texture_filter", --texture-filter):
    // bilinear, or bicubic when asked (shading/mip_pyramid.h).
    TextureFilter texture_filter = TextureFilter::Bilinear;
    // Passes until a time or a noise level ("time_limit", "noise_target", "pass_spp",
    // "max_spp"; core/progressive.h), in place of spp.
    ProgressiveSettings progressive;

    // The Whitted integrator's settings (std::get: only when it is the one in use).
    WhittedSettings& whitted() { return std::get<WhittedSettings>(integrator); }
    const WhittedSettings& whitted() const { return std::get<WhittedSettings>(integrator); }

    // The "render" object's settings that are also command-line flags, declared once
    // (core/setting.h): the JSON reader and the command line both read them from here.
    template <typename F>
    void fields(F& f) {
        f.integer({"spp",
                   "samples per pixel, stratified jitter (not used with a time limit or a "
                   "noise target)"},
                  spp, 1, kMaxSpp);
        f.real({"time_limit",
                "progressive: stop after the pass that crosses this many seconds of rendering "
                "(docs/path-tracing.md)"},
               progressive.time_limit, 1e-3, 1e9);
        f.real({"noise_target",
                "progressive: stop when the estimated relative RMS noise of the image falls to "
                "this (0.02 is 2%; at least 4 passes)"},
               progressive.noise_target, 1e-6, 10.0);
        f.integer({"pass_spp", "progressive: samples per pixel of each pass"}, progressive.pass_spp,
                  2, 1024);
        f.integer({"max_spp", "progressive: the most samples a pixel gets, in whole passes"},
                  progressive.max_spp, 2, kMaxSpp);
        f.integer({"tile_size", "tile side in pixels, a multiple of 16"}, tile_size, kCoherentBlock,
                  kMaxTileSize);
        f.choice({"aa",
                  "stratified (spp jittered samples per pixel), adaptive (corner subdivision, "
                  "POV-Ray's recursive method) or corners (the mean of the four pixel corners, "
                  "(W+1)x(H+1) rays: the SPD's procedure; docs/antialiasing.md)"},
                 aa,
                 {{"stratified", AntiAliasing::Stratified},
                  {"adaptive", AntiAliasing::Adaptive},
                  {"corners", AntiAliasing::Corners}});
        f.real({"aa_threshold",
                "adaptive: subdivide while corners differ by more than this (sum of the absolute "
                "RGBA differences)"},
               adaptive.threshold, 0.0, 1e30);
        f.integer({"aa_depth", "adaptive: at most this many subdivisions per pixel"},
                  adaptive.depth, 0, kMaxAdaptiveDepth);
        f.choice(
            {"gi",
             "global illumination: none, or radiosity (a pre-pass over the surfaces' "
             "patches, the scene's \"radiosity\" settings; docs/radiosity.md)"},
            gi, {{"none", GlobalIllumination::None}, {"radiosity", GlobalIllumination::Radiosity}});
        f.real({"texture_cache_mb",
                "image textures: decoded tiles held at once, MB (docs/textures.md)",
                "--texture-cache"},
               texture_cache_mb, 1.0, 1e6);
        f.choice({"texture_filter",
                  "image textures: the filter within a MIP level, bilinear (default) or bicubic "
                  "(smoother magnified, 4x4 texels; docs/textures.md)",
                  "--texture-filter"},
                 texture_filter,
                 {{"bilinear", TextureFilter::Bilinear}, {"bicubic", TextureFilter::Bicubic}});
        f.choice({"sphere_math", "stable (default), seed (seed 000's algebraic form) or double"},
                 sphere_math,
                 {{"stable", SphereMath::Stable},
                  {"seed", SphereMath::Seed},
                  {"double", SphereMath::Double}});
    }
    // What the fields cannot say alone.
    std::optional<FieldProblem> problem() const {
        if (!valid_tile_size(tile_size)) {
            return FieldProblem{"tile_size", "expected " + tile_size_expectation() + ", got " +
                                                 std::to_string(tile_size)};
        }
        if (progressive.enabled() && aa != AntiAliasing::Stratified) {
            return FieldProblem{"aa",
                                "adaptive and corner antialiasing have their own stopping rule; a "
                                "time limit or noise target renders stratified passes"};
        }
        if (progressive.enabled() && progressive.max_spp < progressive.pass_spp) {
            return FieldProblem{"max_spp", std::to_string(progressive.max_spp) +
                                               " is below one pass of pass_spp " +
                                               std::to_string(progressive.pass_spp) + " samples"};
        }
        return std::nullopt;
    }
};

struct SceneDescription {
    std::string source;  // file path, or "<default>" for the built-in scene
    Scene scene;
    ShadingScene shading;
    RenderSettings settings;
    // Input that was dropped rather than refused (e.g. zero-area patches of a tessellation),
    // each "where: what"; the CLI prints them. skipped_triangles counts the triangles they held.
    std::vector<std::string> warnings;
    // The files the scene's file referenced, as read (load_scene_file; the resume fingerprint).
    std::vector<InputFileRecord> input_files;
    size_t skipped_triangles = 0;
    // The "method" of top-level objects that name one (objects without stay analytic).
    std::vector<ShapeMethodRequest> shape_methods;
    // The methods the reader chose for objects it reads straight into their form (voxel grids
    // and height fields: `auto`), one line each for --stats: "voxels /objects/3 (auto): mesh,
    // 42216 triangles (<= 671088, ~4 MB)".
    std::vector<std::string> method_choices;
    // Model files (apps/scene/model_scene.h): the cameras the file defines (scene.camera is the
    // one in use) and the names of shading.lights where the file names them (else empty).
    std::vector<GltfCamera> file_cameras;
    std::vector<std::string> light_names;
};

}  // namespace rayo
