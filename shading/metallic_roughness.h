#pragma once
// The glTF metallic-roughness workflow on rayo's Phong model (docs/scene-format.md, "glTF
// materials"; docs/models.md, "Metallic, roughness and occlusion textures"): used by the glTF
// loader for the material's factors and by the integrator for each hit of a material with a
// metallicRoughnessTexture.
#include "shading/material.h"

namespace rayo {

// Sets ka, kd, ks, reflect and shininess of `c` from the base colour, metallic and roughness
// (glTF 2.0 specification, Appendix B): F0 = mix(0.04, base, metallic), kd = (1 − metallic)·base,
// ka = 0.1·base, ks = F0, reflect = (1 − r)²·F0, shininess = 2/r⁴ − 2 clamped to [1, 10000].
void apply_metallic_roughness(SurfaceCoefficients& c, const Vec3& base, float metallic,
                              double roughness);

// glTF occlusionTexture: the factor 1 + strength·(occlusion − 1) that multiplies the ambient
// term (glTF 2.0, 3.9.3: lerp(colour, colour·occlusion, strength)).
inline float occlusion_factor(float occlusion, float strength) {
    return 1.0f + strength * (occlusion - 1.0f);
}

}  // namespace rayo
