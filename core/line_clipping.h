#pragma once
// Cohen–Sutherland line clipping to an axis-aligned rectangle (seed 003 §1.3, figs. 1.8–1.10):
// each end point gets a 4-bit region code, a segment whose codes share a bit is rejected whole,
// one whose codes are both 0000 is kept whole, and otherwise an outside end is moved to the
// border it is outside of (eqs. 1.1, 1.2) until one of the first two cases holds.
#include <cstdint>
#include <glm/vec2.hpp>

namespace rayo {

using DVec2 = glm::dvec2;

// The region-code bits, written as the seed writes them (x_min first): "1000" is left of x_min,
// "0100" right of x_max, "0010" below y_min, "0001" above y_max (seed 003: A = 1000 is clipped
// at x = x_min, B = 0001 at y = y_max). 0000 is inside (borders included).
enum RegionBits : uint8_t {
    kLeftOfXMin = 0b1000,
    kRightOfXMax = 0b0100,
    kBelowYMin = 0b0010,
    kAboveYMax = 0b0001,
};

struct ClipRect {
    double x_min = 0.0, y_min = 0.0, x_max = 1.0, y_max = 1.0;  // x_min <= x_max, y_min <= y_max
};

// The seed's region code of `p` (fig. 1.8).
uint8_t region_code(const ClipRect& rect, const DVec2& p);

// Clips the segment a–b to `rect` in place. Returns false when nothing of it lies in the
// rectangle (the codes share a bit, or every crossing point lies outside); the end points are
// then unspecified.
bool clip_segment(const ClipRect& rect, DVec2& a, DVec2& b);

}  // namespace rayo
