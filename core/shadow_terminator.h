#pragma once
// The shadow terminator of smooth-shaded triangles. A coarse mesh with interpolated normals is
// shaded as if it were the smooth surface, but its shadow rays start on the flat triangle,
// below that surface: where the light grazes the mesh they hit the neighbouring triangles and
// the lit side shows the polygon outline as stair-step shadows. Hanika ("Hacking the Shadow
// Terminator", Ray Tracing Gems II, ch. 4, 2021) moves the shadow ray's origin onto a curved
// surface the vertex normals imply: for each corner A_i with unit normal n_i, the hit point P
// is projected onto the corner's tangent plane when it lies below it,
//     P_i = P − min(0, (P − A_i)·n_i)·n_i,
// and the origin is the barycentric blend P' = Σ w_i·P_i. On a flat region (all n_i equal to
// the face normal) P' = P; the offset is at most the triangle's deviation from the smooth
// surface. Only shadow rays start from P' (reflections keep P).
#include "core/math.h"

namespace rayo {

// P' − P for the hit P = Σ w_i·corners[i] on a triangle with (not necessarily unit) vertex
// normals pointing to the side the shadow rays leave from; zero where a normal is zero.
inline Vec3 terminator_offset(const Vec3& position, const Vec3 (&corners)[3],
                              const Vec3 (&normals)[3], const float (&weights)[3]) {
    Vec3 offset(0.0f);
    for (int i = 0; i < 3; ++i) {
        const float length = glm::length(normals[i]);
        if (!(length > 0.0f)) return Vec3(0.0f);
        const Vec3 unit = normals[i] / length;
        const float below = glm::min(0.0f, glm::dot(position - corners[i], unit));
        offset -= (weights[i] * below) * unit;
    }
    return offset;
}

}  // namespace rayo
