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
        const double x = std::floor(p.x + 0.5), y = std::floor(p.y + 0.5);
        if (x >= 0.0 && y >= 0.0 && x < film.width() && y < film.height()) {
            film.set(static_cast<int>(x), static_cast<int>(y), rgb, 1.0f);
        }
    }
}

}  // namespace rayo
