#include "core/shapes/icosphere.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace rayo {

Icosphere make_icosphere(int level) {
    Icosphere s;
    // The 12 vertices of an icosahedron: cyclic permutations of (0, ±1, ±φ).
    const float phi = (1.0f + std::sqrt(5.0f)) / 2.0f;
    const Vec3 corners[12] = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                              {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                              {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
    for (const Vec3& c : corners) s.positions.push_back(glm::normalize(c));
    s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto found = midpoints.find(key);
            if (found != midpoints.end()) return found->second;
            s.positions.push_back(glm::normalize(s.positions[a] + s.positions[b]));
            const auto index = static_cast<uint32_t>(s.positions.size() - 1);
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<std::array<uint32_t, 3>> finer;
        finer.reserve(s.triangles.size() * 4);
        for (const auto& t : s.triangles) {
            const uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]),
                           ca = midpoint(t[2], t[0]);
            finer.push_back({t[0], ab, ca});
            finer.push_back({t[1], bc, ab});
            finer.push_back({t[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        s.triangles = std::move(finer);
    }
    return s;
}

}  // namespace rayo
