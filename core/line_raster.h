#pragma once
// Line drawing into the float RGBA film for the wireframe preview: a DDA that sets one pixel per
// step along the segment's major axis (no antialiasing: the lines are for framing, not beauty).
#include "core/film.h"
#include "core/line_clipping.h"

namespace rayo {

// Sets the pixels of the segment a–b, given in film coordinates ((i, j) is the centre of pixel
// (i, j)), to `rgb` with alpha 1: pixel (round(x), round(y)) at each of max(|Δx|, |Δy|) + 1
// evenly spaced points. Points outside the window [−½, w − ½] × [−½, h − ½] are skipped
// (clip first: core/line_clipping.h).
void draw_line(Film& film, const DVec2& a, const DVec2& b, const Vec3& rgb);

}  // namespace rayo
