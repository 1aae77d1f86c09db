#pragma once
// What a material says about its image textures (docs/textures.md, "Image textures"): the images
// (encoded bytes, decoded by OpenImageIO from memory), their samplers and texture-coordinate
// transforms, and how the texels become its coefficients. The lookups: shading/image_texture.h.
#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <string>

#include "core/math.h"

namespace rayo {

// Addressing outside [0, 1] (glTF sampler wrapS/wrapT: REPEAT, CLAMP_TO_EDGE,
// MIRRORED_REPEAT).
enum class TextureWrap { Repeat, Clamp, Mirror };

// How the texel values are encoded: sRGB (8- and 16-bit images by convention; glTF requires it
// for base colour and emission), linear, or Auto: linear for float images, sRGB otherwise.
enum class TextureEncoding { Auto, Srgb, Linear };

// One image as loaded: its encoded bytes (PNG, JPEG, EXR, ... as read from the file, a .glb
// buffer view or a data URI; decoded by OpenImageIO from memory, nothing is written to disk)
// and the name messages use.
struct ImageSource {
    std::string name;  // the file path, or "model.glb image 3"
    std::string bytes;
};

// One use of an image by a material: the image, the sampler, and the texture-coordinate
// transform (KHR_texture_transform, MTL -s/-o): (s, t, 1) = transform · (u, v, 1), with (s, t)
// in OpenImageIO's convention, (0, 0) the top-left corner of the image.
struct ImageMap {
    std::shared_ptr<const ImageSource> image;  // null: no image
    TextureWrap wrap_s = TextureWrap::Repeat;
    TextureWrap wrap_t = TextureWrap::Repeat;
    TextureEncoding encoding = TextureEncoding::Auto;
    glm::mat3 transform{1.0f};
    bool used() const { return image != nullptr; }
};

// A colour from an image: the coefficient is offset + scale·texel per channel (linear RGB), so
// that a factor multiplies the texel (MTL Kd·map_Kd, glTF baseColorFactor·baseColorTexture) and
// the glTF metallic workflow's highlight F0 = mix(0.04, base, metallic) follows the texture.
struct ImageTerm {
    bool used = false;
    Vec3 offset{0.0f};
    Vec3 scale{1.0f};
    Vec3 apply(const Vec3& texel) const { return offset + scale * texel; }
};

// glTF metallicRoughnessTexture and occlusionTexture (linear values, docs/models.md): at each hit
// the metallic workflow (shading/metallic_roughness.h) is redone with base colour = base_factor ×
// the base texel (the factor alone without a base image), metallic = metallic_factor × B and
// roughness = roughness_factor × G of `metallic_roughness`; the ambient coefficient is multiplied
// by 1 + occlusion_strength·(R − 1) of `occlusion`.
struct PbrImages {
    ImageMap metallic_roughness;
    Vec3 base_factor{1.0f};
    float metallic_factor = 1.0f;
    float roughness_factor = 1.0f;
    ImageMap occlusion;
    float occlusion_strength = 1.0f;
    bool used() const { return metallic_roughness.used() || occlusion.used(); }
};

// Holes in a surface (docs/models.md, "Cutouts"; glTF alphaMode MASK, MTL map_d): the
// coverage alpha = factor × the image's alpha (or, with `luminance` and an image without an
// alpha channel, its luminance; 1 without an image); alpha < cutoff is a hole, for every ray.
struct MaterialCutout {
    bool enabled = false;
    ImageMap image;
    float factor = 1.0f;
    float cutoff = 0.5f;
    bool luminance = false;
};

// The image textures of a material. `base` drives ka, kd, ks and reflect through their terms
// (each term unused leaves its coefficient constant); `specular` multiplies ks (MTL map_Ks);
// `emission` multiplies the emission (glTF emissiveTexture × emissiveFactor, MTL map_Ke × Ke);
// `pbr` the glTF metallic-roughness and occlusion images. `normal` is a
// tangent-space normal map (glTF normalTexture, MTL norm; its x and y times normal_scale),
// `bump` a height map (MTL map_bump/bump; heights times bump_scale, -bm): both perturb the
// shading normal (docs/models.md, "Normal and bump maps").
struct MaterialImages {
    ImageMap base;
    ImageTerm ka, kd, ks, reflect;
    ImageMap specular;
    ImageMap emission;
    PbrImages pbr;
    ImageMap normal;
    float normal_scale = 1.0f;
    ImageMap bump;
    float bump_scale = 1.0f;
    MaterialCutout cutout;
    bool any() const {
        return base.used() || specular.used() || emission.used() || pbr.used() || normal.used() ||
               bump.used() || cutout.image.used();
    }
};

}  // namespace rayo
