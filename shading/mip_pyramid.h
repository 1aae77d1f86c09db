#pragma once
// rayo's own MIP map of an image texture (docs/textures.md, "Lookups"): the image decoded once
// when the render starts, its levels halved with a box filter down to 1 × 1, and looked up
// trilinearly: the level whose texels match the footprint (Williams 1983), bilinear — or, when
// asked, B-spline bicubic — within each of the two nearest levels, blended linearly. Every
// texel is held as RGBA, 8 bits a channel for 8-bit images and float otherwise; a lookup
// allocates nothing, locks nothing and reads at most 2 × 16 texels. ImageTextures
// (shading/image_texture.h) builds one per image that fits the texture memory limit and leaves
// the others to OpenImageIO's cache.
#include <cstddef>
#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

#include "shading/image_map.h"

namespace rayo {

// The filter within a MIP level: bilinear (2 × 2 texels; the default) or the uniform cubic
// B-spline (4 × 4 texels, smoother under magnification; render.texture_filter, --texture-filter).
enum class TextureFilter { Bilinear, Bicubic };

class MipPyramid {
  public:
    // Level 0 from `pixels`: width × height texels of `channels` interleaved values, 8-bit
    // (0–255) or float. One channel is grey (copied to RGB), two grey and alpha, three RGB,
    // four or more RGBA (the rest ignored); alpha is 1 without one. width, height ≥ 1.
    MipPyramid(int width, int height, int channels, const uint8_t* pixels);
    MipPyramid(int width, int height, int channels, const float* pixels);

    // The bytes a pyramid of a width × height image takes (every level, RGBA), before it is
    // built: what the texture memory limit is checked against.
    static size_t bytes_for(int width, int height, bool floating);
    size_t bytes() const;
    int levels() const { return static_cast<int>(m_levels.size()); }
    int width(int level) const { return m_levels[static_cast<size_t>(level)].width; }
    int height(int level) const { return m_levels[static_cast<size_t>(level)].height; }
    // Texel (x, y) of `level` (0 the image), in [0, 1] for 8-bit images.
    glm::vec4 texel(int level, int x, int y) const;

    // RGBA at (s, t) ((0, 0) the top-left corner, 1 the image's width and height) for a
    // footprint `width` in the same units (the pixel's extent on the surface; 0 or less: the
    // image itself, magnified): the level of log2(width × the larger side), trilinear.
    glm::vec4 lookup(float s, float t, float width, TextureWrap wrap_s, TextureWrap wrap_t,
                     TextureFilter filter) const;
    // The same within one level (tests).
    glm::vec4 sample_level(int level, float s, float t, TextureWrap wrap_s, TextureWrap wrap_t,
                           TextureFilter filter) const;

  private:
    struct Level {
        int width = 0, height = 0;
        size_t offset = 0;  // first texel, in texels
    };
    template <typename T>
    void build(int width, int height, int channels, const T* pixels);
    template <typename T>
    glm::vec4 sample(const T* texels, const Level& level, float s, float t, TextureWrap wrap_s,
                     TextureWrap wrap_t, TextureFilter filter) const;

    std::vector<Level> m_levels;
    bool m_floating = false;
    std::vector<uint8_t> m_bytes;  // RGBA8 texels of every level (8-bit images)
    std::vector<float> m_floats;   // RGBA float texels of every level (the others)
};

}  // namespace rayo
