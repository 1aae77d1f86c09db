#pragma once
// The cutouts of a scene's materials (docs/models.md, "Cutouts"): core's CutoutTest
// (core/cutout.h) answered from MaterialImages::cutout and the render's image textures.
#include <vector>

#include "core/cutout.h"
#include "shading/image_texture.h"
#include "shading/material.h"

namespace rayo {

class MaterialCutouts : public CutoutTest {
  public:
    // `images` may be null when no material names an image (constant alphas only); both must
    // outlive this.
    MaterialCutouts(const std::vector<Material>& materials, const ImageTextures* images);

    // Whether any material has holes (an accel needs this test at all).
    bool any() const { return m_any; }
    bool cuts(uint32_t material) const override;
    bool hole(uint32_t material, const glm::vec2& uv) const override;
    // The coverage alpha of `material` at `uv` (MaterialCutout): point-sampled, the same for
    // every ray whatever its footprint.
    float alpha(uint32_t material, const glm::vec2& uv) const;

  private:
    const std::vector<Material>& m_materials;
    const ImageTextures* m_images;
    bool m_any = false;
};

}  // namespace rayo
