#pragma once
// The Phong local illumination model (seed 000 eqs. [15]-[28], seed 003 eq. 2.9): the diffuse
// and specular terms of one light at one surface point. The ambient term Ka·Ia and the sum over
// lights with shadows and attenuation are in the Whitted integrator.
#include <cmath>

#include "core/math.h"
#include "shading/material.h"

namespace rayo {

// Lambert: Kd·(N·L), only for N·L > 0 (seed 000 eq. [18]).
inline Vec3 lambert_term(const SurfaceCoefficients& m, const Vec3& normal, const Vec3& to_light) {
    const float n_dot_l = glm::dot(normal, to_light);
    return n_dot_l > 0.0f ? m.kd * n_dot_l : Vec3(0.0f);
}

// Specular: Ks·(V·R)^n with R = 2(N·L)N − L (seed 000 eqs. [23]-[25]) or Ks·(N·H)^n (eq. [28])
// with H = (L+V)/|L+V| (eq. [26]). No highlight when the light is below the surface.
inline Vec3 specular_term(const SurfaceCoefficients& m, const Vec3& normal, const Vec3& to_light,
                          const Vec3& to_eye) {
    const float n_dot_l = glm::dot(normal, to_light);
    // No highlight to compute for Ks = 0 (NFF's matte surfaces carry exponents like 100000).
    if (n_dot_l <= 0.0f || m.ks == Vec3(0.0f)) return Vec3(0.0f);
    float cosine;
    if (m.specular_model == SpecularModel::Phong) {
        const Vec3 reflected = 2.0f * n_dot_l * normal - to_light;
        cosine = glm::dot(to_eye, reflected);
    } else {
        const Vec3 half_sum = to_light + to_eye;
        const float length = glm::length(half_sum);
        cosine = length > 0.0f ? glm::dot(normal, half_sum / length) : 0.0f;
    }
    return cosine > 0.0f ? m.ks * std::pow(cosine, m.shininess) : Vec3(0.0f);
}

// Diffuse plus specular for one light of radiance `light` (Ii·f(d)): seed 000 eq. [24]/[28].
inline Vec3 phong_direct(const SurfaceCoefficients& m, const Vec3& normal, const Vec3& to_light,
                         const Vec3& to_eye, const Vec3& light) {
    return light * (lambert_term(m, normal, to_light) + specular_term(m, normal, to_light, to_eye));
}

}  // namespace rayo
