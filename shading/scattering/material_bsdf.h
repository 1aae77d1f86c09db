#pragma once
// A material's coefficients at a surface interaction (shading/surface_interaction.h) as a
// scattering function that answers eval, sample and pdf (bsdf.h), for the integrators that
// sample directions; Whitted keeps shading the coefficients with seed 000's local model
// (shading/phong.h). The mapping, lobe by lobe:
//   glTF metallic-roughness materials -> the glTF model itself (metallic_roughness_bsdf.h),
//   otherwise kd -> Lambert; ks, shininess -> the normalised modified Phong lobe
//   (Lafortune & Willems 1994) or Blinn-Phong, as the material's specular model says; transmit
//   (with ior) -> the smooth dielectric (seed 001, exact Fresnel and total internal reflection),
//   else reflect -> the perfect mirror (seed 001); translucency -> seed 001's diffuse transmission.
// Each lobe is chosen in proportion to the largest component of its colour. The dielectric has
// no tint: a transmit colour below 1 is the path tracer's medium to apply (Beer-Lambert).
#include <algorithm>

#include "shading/material.h"
#include "shading/scattering/bsdf.h"

namespace rayo {

inline float lobe_weight(const Vec3& colour) {
    return std::max({colour.x, colour.y, colour.z});
}

inline Bsdf material_bsdf(const SurfaceCoefficients& m) {
    Bsdf bsdf;
    if (m.metallic_roughness.used) {
        const auto& p = m.metallic_roughness;
        bsdf.add(MetallicRoughnessBsdf(p.base_color, p.metallic, p.roughness));
        return bsdf;
    }
    if (m.kd != Vec3(0.0f)) bsdf.add(Lambert(m.kd), lobe_weight(m.kd));
    if (m.ks != Vec3(0.0f)) {
        if (m.specular_model == SpecularModel::Blinn) {
            bsdf.add(BlinnPhong(m.ks, m.shininess), lobe_weight(m.ks));
        } else {
            bsdf.add(ModifiedPhong(m.ks, m.shininess), lobe_weight(m.ks));
        }
    }
    if (m.transmissive()) {
        bsdf.add(Dielectric(m.ior), std::max(lobe_weight(m.transmit), lobe_weight(m.reflect)));
    } else if (m.reflective()) {
        bsdf.add(Mirror(m.reflect), lobe_weight(m.reflect));
    }
    if (m.translucent()) bsdf.add(DiffuseTransmission(m.translucency), lobe_weight(m.translucency));
    return bsdf;
}

}  // namespace rayo
