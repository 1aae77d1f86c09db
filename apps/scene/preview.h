#pragma once
// The wireframe preview of a scene (`rayo preview`, docs/preview.md): the outlines of every
// object (core/wireframe.h) drawn over black, or over a dim one-sample render of the scene, to
// frame a long render in well under a second.
#include "apps/scene/scene_description.h"
#include "core/film.h"
#include "core/wireframe.h"

namespace rayo {

struct PreviewOptions {
    bool over_render = false;  // draw over a 1 spp render of the scene, darkened
    float render_gain = 0.2f;  // what the render's RGB is multiplied by under the lines
    Vec3 line_rgb{1.0f, 0.8f, 0.25f};
    int threads = 0;  // for the render under the lines; 0: all cores
};

struct PreviewResult {
    Film film{1, 1};
    WireframeStats stats;
    double render_seconds = 0.0;  // the dim render (BVH and tracing), 0 without one
    double draw_seconds = 0.0;    // outlines, projection, clipping and lines
};

// Throws InputError for an invalid camera (named as render_scene names it).
PreviewResult render_preview(const SceneDescription& description, const PreviewOptions& options);

}  // namespace rayo
