#pragma once
// The local shading frame of the scattering lobes (z = shading normal): an orthonormal basis from a
// unit normal (Duff et al. 2017, "Building an Orthonormal Basis, Revisited"), world <-> local, and
// cosine-weighted hemisphere sampling (Malley's method on Shirley & Chiu 1997's concentric map).
#include <algorithm>
#include <cmath>
#include <glm/vec2.hpp>

#include "core/math.h"
#include "core/sampling.h"

namespace rayo {

// A right-handed orthonormal basis: tangent × bitangent = normal.
struct LocalFrame {
    Vec3 tangent{1.0f, 0.0f, 0.0f};
    Vec3 bitangent{0.0f, 1.0f, 0.0f};
    Vec3 normal{0.0f, 0.0f, 1.0f};

    // Duff et al. 2017, listing 3: branch-free apart from the sign, continuous everywhere except
    // across z = 0 with n.x = n.y = 0, and exact for n = (0, 0, ±1) (Frisvad 2012's form breaks
    // near (0, 0, −1)). `n` must be unit length.
    static LocalFrame from_normal(const Vec3& n) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        LocalFrame f;
        f.tangent = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        f.bitangent = Vec3(b, sign + n.y * n.y * a, -n.y);
        f.normal = n;
        return f;
    }

    Vec3 to_local(const Vec3& v) const {
        return Vec3(glm::dot(v, tangent), glm::dot(v, bitangent), glm::dot(v, normal));
    }
    Vec3 to_world(const Vec3& v) const { return v.x * tangent + v.y * bitangent + v.z * normal; }
};

// Local-frame predicates the two-sided lobes share.
inline bool same_hemisphere(const Vec3& a, const Vec3& b) {
    return a.z * b.z > 0.0f;
}
// The mirror image through the tangent plane: a two-sided lobe evaluates a wo below the surface
// as its image above, with wi mirrored alike (a reflection keeps every dot product).
inline Vec3 flip_z(const Vec3& v) {
    return Vec3(v.x, v.y, -v.z);
}

// The unit vector at polar angle θ (given as cos θ) and azimuth φ about +z.
inline Vec3 spherical_direction(float cos_theta, float phi) {
    const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    return Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

// Malley's method: points uniform on the unit disk lifted to the hemisphere z > 0 have the
// density cos θ/π. The concentric map keeps the strata of u compact on the hemisphere.
inline Vec3 sample_cosine_hemisphere(const glm::vec2& u) {
    const glm::vec2 d = concentric_disk(u);
    const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return Vec3(d.x, d.y, z);
}

inline float cosine_hemisphere_pdf(float cos_theta) {
    return cos_theta > 0.0f ? cos_theta / kPi : 0.0f;
}

// u in [0, 1) split at p into [0, p) and [p, 1), each mapped back onto [0, 1): one random number
// both chooses a branch and samples it. Clamped below 1, which rounding could otherwise reach.
inline float remap_below(float u, float p) {
    return std::min(u / p, 0x1.fffffep-1f);
}
inline float remap_above(float u, float p) {
    return std::min((u - p) / (1.0f - p), 0x1.fffffep-1f);
}

}  // namespace rayo
