#pragma once
// Cutouts (docs/models.md, "Cutouts"): surfaces whose material has holes (MTL map_d, glTF
// alphaMode MASK). Core knows nothing of materials or images: the accel asks this interface,
// which shading implements (shading/cutouts.h), and registers Embree intersection and occlusion
// filters only on the meshes with a cut material, so that no other geometry's rays change.
#include <cstdint>
#include <glm/vec2.hpp>

namespace rayo {

class CutoutTest {
  public:
    virtual ~CutoutTest() = default;
    // Whether surfaces of `material` may have holes (the mesh gets the filters).
    virtual bool cuts(uint32_t material) const = 0;
    // Whether the surface of `material` at texture coordinates `uv` is a hole: a hit there is no
    // hit, for every ray. Thread-safe.
    virtual bool hole(uint32_t material, const glm::vec2& uv) const = 0;
};

}  // namespace rayo
