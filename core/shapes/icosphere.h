#pragma once
// A unit icosphere: the icosahedron with each triangle split into four `level` times, vertices
// pushed onto the sphere. 20·4^level triangles, 10·4^level + 2 vertices. Used to tessellate
// spheres for the `mesh:N` sphere method.
#include <array>
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace rayo {

struct Icosphere {
    std::vector<Vec3> positions;                     // unit length; also the smooth vertex normals
    std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise seen from outside
};

Icosphere make_icosphere(int level);

// Deepest point of any face below the unit sphere (1 − the smallest distance from the centre to
// a face plane), for levels 0..7, measured on make_icosphere's output (tests/sphere_method_test
// recomputes it). Subdivided faces are not all equal, so this exceeds the sagitta of the mean edge.
constexpr double kIcosphereMaxDepth[8] = {0.205345554,    0.0658277004,  0.0177530514,
                                          0.0045284067,   0.00113790669, 0.000284817931,
                                          7.12867694e-05, 1.78320694e-05};

}  // namespace rayo
