#pragma once
// Image textures (docs/textures.md, "Image textures"): the images a material names (glTF
// baseColorTexture/emissiveTexture/metallicRoughnessTexture/occlusionTexture/normalTexture, MTL
// map_Kd/map_Ks/map_Ke/norm/map_bump/map_d, JSON {"image": file}), decoded once when the render
// starts into rayo's own MIP maps (shading/mip_pyramid.h) while they fit the texture memory
// limit, and the rest through one OpenImageIO TextureSystem per render (mip-mapped, cached,
// bounded by what the MIP maps left of the limit).
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <string>
#include <vector>

#include "shading/image_map.h"
#include "shading/mip_pyramid.h"

namespace rayo {

struct Material;

constexpr float kDefaultTextureCacheMB = 256.0f;

struct ImageTextureStats {
    size_t textures = 0;        // distinct images
    size_t mip_mapped = 0;      // of which held as rayo's MIP maps (the rest in OIIO's cache)
    int64_t memory_used = 0;    // bytes of MIP maps and decoded tiles held at the end
    int64_t memory_peak = 0;    // most bytes held at once (the MIP maps + OIIO's peak tiles)
    int64_t encoded_bytes = 0;  // the images' file bytes kept in memory
    float limit_mb = 0.0f;      // the texture memory limit (--texture-cache)
    int64_t image_bytes = 0;    // the images' decoded size (all MIP levels)
};

// The texture system of one render: every material's images registered once (images shared by
// materials are one texture), looked up by the material's index. Thread-safe: lookups from any
// number of threads (the MIP maps are read-only; OpenImageIO keeps per-thread state itself).
class ImageTextures {
  public:
    // Registers the images of `materials` (indexed as the scene's material ids), each checked
    // first as check_texture_fits does (throws InputError). In order, each image whose MIP map
    // (MipPyramid::bytes_for) fits what is left of `max_memory_mb` is decoded into one; from the
    // first that does not, the images go to a TextureSystem whose cache holds at most what is
    // left (at least 1 MB). `filter`: within a MIP level, bilinear or bicubic.
    ImageTextures(const std::vector<Material>& materials, float max_memory_mb,
                  TextureFilter filter = TextureFilter::Bilinear);
    ~ImageTextures();
    ImageTextures(const ImageTextures&) = delete;
    ImageTextures& operator=(const ImageTextures&) = delete;

    // Filtered RGBA of `map` of material `material` at texture coordinates `uv` (before the
    // map's transform) with the footprint `width` in uv units (isotropic: the pixel's extent
    // on the surface in texture coordinates; 0: the image itself, magnified); trilinear between
    // MIP levels; RGB decoded to linear when the image is sRGB. Alpha is 1 for images without
    // one.
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
