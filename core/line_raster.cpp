#include "core/line_raster.h"

#include <algorithm>
#include <cmath>

namespace rayo {

void draw_line(Film& film, const DVec2& a, const DVec2& b, const Vec3& rgb) {
    const DVec2 delta = b - a;
    const double length = std::max(std::abs(delta.x), std::abs(delta.y));
    if (!std::isfinite(length)) return;
    const long steps = static_cast<long>(std::ceil(length));
    for (long i = 0; i <= steps; ++i) {
        const DVec2 p = steps == 0 ? a : a + (static_cast<double>(i) / steps) * delta;
        // Pixel i covers [i − ½, i + ½); the window's far edges (w − ½, h − ½) belong to the
        // last pixel.
        if (!(p.x >= -0.5 && p.y >= -0.5 && p.x <= film.width() - 0.5 &&
              p.y <= film.height() - 0.5)) {
            continue;
        }
        const int x = std::min(static_cast<int>(std::floor(p.x + 0.5)), film.width() - 1);
        const int y = std::min(static_cast<int>(std::floor(p.y + 0.5)), film.height() - 1);
        film.set(x, y, rgb, 1.0f);
    }
}

}  // namespace rayo
