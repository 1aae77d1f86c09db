#include "core/shapes/quadric.h"

#include <cmath>

namespace rayo {

std::optional<FieldProblem> Quadric::problem() const {
    for (double c : coefficients) {
        if (!std::isfinite(c)) return FieldProblem{"coefficients", "expected finite numbers"};
    }
    bool surface = false;  // some of A..I non-zero: J alone is everywhere or nowhere
    for (int i = 0; i < 9; ++i) surface = surface || coefficients[i] != 0.0;
    if (!surface) {
        return FieldProblem{"coefficients",
                            "expected a non-zero quadratic or linear part (A..I not all 0)"};
    }
    if (!(clip.lower.x < clip.upper.x && clip.lower.y < clip.upper.y &&
          clip.lower.z < clip.upper.z)) {
        return FieldProblem{"bounds/max", "expected max > min on every axis"};
    }
    return std::nullopt;
}

ClippedQuadric Quadric::intersector() const {
    const auto k = [&](int i) { return coefficients[i]; };
    ClippedQuadric q;
    // M = [[A, D/2, E/2], [D/2, B, F/2], [E/2, F/2, C]] (symmetric; glm is column-major).
    q.m = DMat3(k(0), 0.5 * k(3), 0.5 * k(4),  //
                0.5 * k(3), k(1), 0.5 * k(5),  //
                0.5 * k(4), 0.5 * k(5), k(2));
    q.g = DVec3(k(6), k(7), k(8));
    q.j = k(9);
    q.lower = DVec3(clip.lower);
    q.upper = DVec3(clip.upper);
    q.capped = capped;
    return q;
}

}  // namespace rayo
