#include "shading/cutouts.h"

#include "core/luminance.h"

namespace rayo {

MaterialCutouts::MaterialCutouts(const std::vector<Material>& materials,
                                 const ImageTextures* images)
    : m_materials(materials), m_images(images) {
    for (const Material& m : materials) m_any |= m.images.cutout.enabled;
}

bool MaterialCutouts::cuts(uint32_t material) const {
    return material < m_materials.size() && m_materials[material].images.cutout.enabled;
}

float MaterialCutouts::alpha(uint32_t material, const glm::vec2& uv) const {
    const MaterialCutout& cutout = m_materials[material].images.cutout;
    using Slot = ImageTextures::Slot;
    if (m_images == nullptr || !m_images->has(material, Slot::Cutout)) return cutout.factor;
    const glm::vec4 texel = m_images->lookup(material, Slot::Cutout, uv, 0.0f);
    if (cutout.luminance && !m_images->has_alpha(material, Slot::Cutout)) {
        // MTL map_d on an image without alpha: its luminance.
        return cutout.factor * luminance(Vec3(texel));
    }
    return cutout.factor * texel.w;
}

bool MaterialCutouts::hole(uint32_t material, const glm::vec2& uv) const {
    return cuts(material) && alpha(material, uv) < m_materials[material].images.cutout.cutoff;
}

}  // namespace rayo
