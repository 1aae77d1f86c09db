#pragma once
// Phong materials (seed 000 eqs. [22]-[24], seed 003 eq. 2.9): per-channel ambient, diffuse and
// specular coefficients, the specular exponent, and the Whitted transport weights.
#include <cstdint>
#include <string>

#include "core/math.h"
#include "shading/image_map.h"

namespace rayo {

enum class SpecularModel {
    Phong,  // (V·R)^n, seed 000 eq. [24]
    Blinn,  // (N·H)^n, seed 000 eq. [28]
};

// Procedural textures of a material (seed 003 ch. 3): indices into ShadingScene::textures, or
// kNoTexture. A textured ka/kd/ks takes the texture's colour at the hit point; `bump` perturbs the
// shading normal by its gradient (texture.h bump_normal).
constexpr int32_t kNoTexture = -1;

struct MaterialTextures {
    int32_t ka = kNoTexture;
    int32_t kd = kNoTexture;
    int32_t ks = kNoTexture;
    int32_t bump = kNoTexture;
    float bump_strength = 1.0f;
    float ka_scale = 1.0f;  // multiplies a textured ka (the JSON default ka = 0.1 × kd's texture)

    bool any() const { return ka >= 0 || kd >= 0 || ks >= 0 || bump >= 0; }
};

// The coefficients a hit shades with: the local model's and the transport weights. A textured
// material's coefficients at a hit are a copy of these with ka/kd/ks replaced (no name copied).
struct SurfaceCoefficients {
    Vec3 ka{0.1f};            // ambient, multiplies the scene's ambient light
    Vec3 kd{0.8f};            // diffuse (Lambert)
    Vec3 ks{0.0f};            // specular highlight
    float shininess = 32.0f;  // exponent n
    SpecularModel specular_model = SpecularModel::Phong;
    Vec3 reflect{0.0f};   // perfect mirror weight, seed 001
    Vec3 transmit{0.0f};  // perfect specular transmission weight, seed 001
    float ior = 1.0f;     // index of refraction of the inside (outside is 1)
    // Fresnel weights (seed 000's W(θ)): reflect·F(θ) and transmit·(1 − F(θ)) with F the
    // dielectric reflectance for `ior` (optics.h fresnel_reflectance) instead of the constants.
    bool fresnel = false;
    Vec3 translucency{0.0f};  // perfect diffuse transmission, seed 001: lights behind the surface
    Vec3 absorption{0.0f};    // Beer–Lambert σ per unit length inside the object (seed 004)
    Vec3 emission{0.0f};      // radiance the surface sends to every ray that sees an emitting side
    // Two-sided (the default): both sides of the surface are the same surface, each with its own
    // light. The back (the side the geometric normal points away from) emits, and in the
    // radiosity solve receives and reflects, as the front does: real assets are not wound
    // consistently. One-sided (JSON "double_sided": false, glTF doubleSided false, an area
    // light's own surface): only the front emits and holds a radiosity patch; the back keeps
    // what each integrator did before (docs/radiosity.md, docs/path-tracing.md).
    bool double_sided = true;
    // The light (index into ShadingScene::lights) that samples this emitter's surface, whose pdf
    // a sampling integrator weighs a hit on it with (multiple importance sampling: the area
    // lights' own surfaces, apps/scene/area_light_emitters.h); -1: no light samples it.
    int32_t emitter_light = -1;
    // The glTF metallic-roughness parameters the Phong coefficients above were mapped from
    // (shading/metallic_roughness.h), kept for the integrators that sample the physically based
    // model itself (shading/scattering/material_bsdf.h); Whitted shades the mapping.
    struct MetallicRoughness {
        bool used = false;
        Vec3 base_color{1.0f};
        float metallic = 0.0f, roughness = 1.0f;
    } metallic_roughness;

    bool transmissive() const {
        return transmit.x > 0.0f || transmit.y > 0.0f || transmit.z > 0.0f;
    }
    bool reflective() const { return reflect.x > 0.0f || reflect.y > 0.0f || reflect.z > 0.0f; }
    bool translucent() const { return translucency != Vec3(0.0f); }
    bool absorbing() const { return absorption != Vec3(0.0f); }
    bool emissive() const { return emission != Vec3(0.0f); }
    // Whether a ray arriving on the front (`front`) or the back sees the emission.
    bool emits_toward(bool front) const { return emissive() && (front || double_sided); }
    // Whether lights change its colour at all (a pure emitter, such as an area light's own
    // surface, needs no shadow rays).
    bool lit() const { return kd != Vec3(0.0f) || ks != Vec3(0.0f) || translucent(); }
};

struct Material : SurfaceCoefficients {
    std::string name;
    MaterialTextures textures;  // none by default: the constant coefficients
    MaterialImages images;      // image textures (shading/image_map.h); none by default
};

}  // namespace rayo
