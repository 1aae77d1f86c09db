#include "core/line_clipping.h"

#include <cmath>
#include <utility>

namespace rayo {

uint8_t region_code(const ClipRect& rect, const DVec2& p) {
    uint8_t code = 0;
    if (p.x < rect.x_min) code |= kLeftOfXMin;
    if (p.x > rect.x_max) code |= kRightOfXMax;
    if (p.y < rect.y_min) code |= kBelowYMin;
    if (p.y > rect.y_max) code |= kAboveYMax;
    return code;
}

bool clip_segment(const ClipRect& rect, DVec2& a, DVec2& b) {
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) {
        return false;
    }
    uint8_t code_a = region_code(rect, a);
    uint8_t code_b = region_code(rect, b);
    // Each pass moves one outside end onto a border and clears that border's bit, so at most
    // four passes per end; the bound only guards against a non-terminating loop.
    for (int pass = 0; pass < 8; ++pass) {
        if ((code_a | code_b) == 0) return true;   // both 0000: drawn whole
        if ((code_a & code_b) != 0) return false;  // both beyond one border: discarded
        // Move an end that is outside (a first), along γ(t) = a + t(b − a) (eqs. 1.1, 1.2).
        const bool move_a = code_a != 0;
        DVec2& p = move_a ? a : b;
        const DVec2& q = move_a ? b : a;
        const uint8_t code = move_a ? code_a : code_b;
        if (code & kLeftOfXMin) {
            p = DVec2(rect.x_min, p.y + (rect.x_min - p.x) / (q.x - p.x) * (q.y - p.y));
        } else if (code & kRightOfXMax) {
            p = DVec2(rect.x_max, p.y + (rect.x_max - p.x) / (q.x - p.x) * (q.y - p.y));
        } else if (code & kBelowYMin) {
            p = DVec2(p.x + (rect.y_min - p.y) / (q.y - p.y) * (q.x - p.x), rect.y_min);
        } else {
            p = DVec2(p.x + (rect.y_max - p.y) / (q.y - p.y) * (q.x - p.x), rect.y_max);
        }
        (move_a ? code_a : code_b) = region_code(rect, p);
    }
    return (code_a | code_b) == 0;
}

}  // namespace rayo
