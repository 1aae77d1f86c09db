#pragma once
// Image textures (docs/textures.md, "Image textures"): the images a material names (glTF
// baseColorTexture/emissiveTexture/metallicRoughnessTexture/occlusionTexture/normalTexture, MTL
// map_Kd/map_Ks/map_Ke/norm/map_bump/map_d, JSON {"image": file}) and one
// OpenImageIO TextureSystem per render that filters them (mip-mapped, cached, memory bounded).
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <string>
#include <vector>

#include "shading/image_map.h"

namespace rayo {

struct Material;

constexpr float kDefaultTextureCacheMB = 256.0f;

struct ImageTextureStats {
    size_t textures = 0;        // distinct images
    int64_t memory_used = 0;    // bytes of decoded tiles held by the cache at the end
    int64_t memory_peak = 0;    // most bytes held at once (OIIO's peak tile memory)
    int64_t encoded_bytes = 0;  // the images' file bytes kept in memory
    float limit_mb = 0.0f;      // the cache's max_memory_MB
    int64_t image_bytes = 0;    // the images' decoded size (all MIP levels OIIO made)
};

// The texture system of one render: every material's images registered once (images shared by
// materials are one texture), looked up by the material's index. Thread-safe: lookups from any
// number of threads (OpenImageIO keeps per-thread state itself).
class ImageTextures {
  public:
    // Registers the images of `materials` (indexed as the scene's material ids) in a new
    // TextureSystem whose cache holds at most `max_memory_mb` of decoded tiles, each image
    // checked first (check_texture_fits: throws InputError).
    ImageTextures(const std::vector<Material>& materials, float max_memory_mb);
    ~ImageTextures();
    ImageTextures(const ImageTextures&) = delete;
    ImageTextures& operator=(const ImageTextures&) = delete;

    // Filtered RGBA of `map` of material `material` at texture coordinates `uv` (before the
    // map's transform) with the footprint `width` in uv units (isotropic: the pixel's extent
    // on the surface in texture coordinates); RGB decoded to linear when the image is sRGB.
    // Alpha is 1 for images without one.
    enum class Slot {
        Base,
        Specular,
        Emission,
        MetallicRoughness,
        Occlusion,
        Normal,
        Bump,
        Cutout
    };
    static constexpr size_t kSlotCount = 8;
    glm::vec4 lookup(uint32_t material, Slot slot, const glm::vec2& uv, float width) const;
    bool has(uint32_t material, Slot slot) const;
    // Whether the image of `slot` has an alpha channel (false without an image).
    bool has_alpha(uint32_t material, Slot slot) const;

    size_t texture_count() const;
    ImageTextureStats stats() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

// Checks that `source`'s header reads as an image of at most kMaxTexturePixels (OpenImageIO
// reads it from memory; no pixel is decoded); false with the reason in `error` otherwise.
bool image_source_readable(const ImageSource& source, std::string& error);
// What the render checks before it registers an image (the ImageTextures constructor): that an
// image without tiles fits the texture cache's limit decoded (its reader holds it whole; a
// 30000 × 30000 PNG took 1.44 GB under the default 256 MB), and that every pixel decodes (a
// truncated PNG used to shade with what libpng had made of it). Throws InputError naming the
// image's file otherwise.
void check_texture_fits(const ImageSource& source, float max_memory_mb);
// The most pixels a texture image may declare, checked from its header before it is decoded: a
// 370-byte PNG declaring 100000 × 100000 took 24 GB (docs/limits.md, "Texture images"). 2^28,
// the height fields' sample limit: 16384 × 16384.
constexpr uint64_t kMaxTexturePixels = uint64_t(1) << 28;

// The sRGB transfer function's inverse (IEC 61966-2-1): encoded [0, 1] -> linear.
float srgb_to_linear(float encoded);

}  // namespace rayo
