#include "shading/normal_mapping.h"

#include <cmath>

#include "shading/texture.h"

namespace rayo {
namespace {

bool usable(const Vec3& v) {
    const float length2 = glm::dot(v, v);
    return length2 > 0.0f && std::isfinite(length2);
}

}  // namespace

glm::vec4 surface_tangent(const Vec3& normal, const Vec3& dpdu, const Vec3& dpdv) {
    if (!usable(dpdu)) return glm::vec4(0.0f);
    const float w = glm::dot(glm::cross(normal, dpdu), -dpdv) < 0.0f ? -1.0f : 1.0f;
    return glm::vec4(dpdu, w);
}

Vec3 tangent_space_normal(const Vec3& normal, const glm::vec4& tangent, const Vec3& texel,
                          float scale) {
    // Gram-Schmidt: T = normalize(t − N(N·t)).
    const Vec3 t(tangent);
    const Vec3 orthogonal = t - normal * glm::dot(normal, t);
    if (tangent.w == 0.0f || !usable(orthogonal)) return normal;
    const Vec3 tangent_unit = glm::normalize(orthogonal);
    const Vec3 bitangent = tangent.w * glm::cross(normal, tangent_unit);
    const Vec3 m = (2.0f * texel - Vec3(1.0f)) * Vec3(scale, scale, 1.0f);
    const Vec3 n = m.x * tangent_unit + m.y * bitangent + m.z * normal;
    return usable(n) ? glm::normalize(n) : normal;
}

Vec3 bump_mapped_normal(const Vec3& normal, const Vec3& dpdu, const Vec3& dpdv, float dfdu,
                        float dfdv) {
    const Vec3 pu = dpdu - normal * glm::dot(normal, dpdu);
    const Vec3 pv = dpdv - normal * glm::dot(normal, dpdv);
    if (!usable(glm::cross(pu, pv))) return normal;
    const Vec3 n = glm::cross(pu + dfdu * normal, pv + dfdv * normal);
    if (!usable(n)) return normal;
    const Vec3 unit = glm::normalize(n);
    // Pu × Pv is ±normal: the side follows the parameterization's orientation.
    return glm::dot(glm::cross(pu, pv), normal) >= 0.0f ? unit : -unit;
}

Vec3 face_viewer(const Vec3& normal, const Vec3& to_eye) {
    const float c = glm::dot(normal, to_eye);
    if (c >= kMinBumpCosine) return normal;
    return glm::normalize(normal + (2.0f * kMinBumpCosine - c) * to_eye);
}

}  // namespace rayo
