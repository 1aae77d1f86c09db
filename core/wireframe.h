#pragma once
// The wireframe of a scene (the preview, docs/preview.md): every shape's and mesh's outline
// (core/shapes/outline.h) seen from the camera's eye, projected by the seed 003 synthetic camera
// (core/synthetic_camera.h), clipped to the window by Cohen–Sutherland (core/line_clipping.h)
// and drawn with a DDA (core/line_raster.h). Pure geometry: no Embree, no shading.
#include <cstddef>

#include "core/camera.h"
#include "core/film.h"
#include "core/scene.h"
#include "core/synthetic_camera.h"

namespace rayo {

struct WireframeStats {
    size_t objects = 0;   // shapes and meshes
    size_t segments = 0;  // outline segments, all of them
    size_t drawn = 0;     // drawn whole or in part
    size_t cut = 0;       // of the drawn, cut at the window's border or at the eye's plane
    size_t outside = 0;   // clipped away: wholly outside the window
    size_t behind = 0;    // clipped away: wholly behind the eye
    size_t clipped_away() const { return outside + behind; }
};

enum class SegmentFate { Whole, Cut, Outside, Behind };

// The part of the 3-D segment a–b that the camera sees, in film coordinates, in `pa`, `pb`: the
// segment is first cut at a plane just in front of the eye (points behind the eye do not
// project, seed 003 §1.2.2), then projected and clipped to the window.
SegmentFate project_segment(const SyntheticCamera& camera, const DVec3& a, const DVec3& b,
                            DVec2& pa, DVec2& pb);

// Draws the outlines of every shape and mesh of `scene` into `film` (the camera's size) in
// `rgb` with alpha 1, over what the film holds.
WireframeStats draw_wireframe(const Scene& scene, const Camera& camera, Film& film,
                              const Vec3& rgb);

}  // namespace rayo
