#pragma once
// The one place a hit becomes a shading point (docs/architecture.md, "The path of one pixel"):
// the side the ray arrived on, the geometric and shading normals facing it, the material's
// coefficients at the hit (procedural textures, seed 003 ch. 3; image textures, the glTF
// metallic-roughness and occlusion maps, vertex colours) and the normal after bump and normal
// maps, and the origin of rays that leave on the arriving side. Every integrator shades from a
// SurfaceInteraction; cutouts are answered earlier, by Embree's hit filters (core/cutout.h).
#include <optional>

#include "core/accel.h"
#include "core/ray.h"
#include "core/surface_hit.h"
#include "shading/image_texture.h"
#include "shading/material.h"
#include "shading/shading_scene.h"

namespace rayo {

struct SurfaceInteraction {
    const SurfaceCoefficients* base = nullptr;    // the scene's material
    std::optional<SurfaceCoefficients> textured;  // its coefficients at the hit, if textured
    bool entering = true;                         // the ray arrived on the geometric normal's side
    Vec3 facing_geometric{0.0f};                  // the geometric normal on the arriving side
    Vec3 normal{0.0f};         // the shading normal on the arriving side, after the maps
    Vec3 to_eye{0.0f};         // −ray direction
    Vec3 shadow_origin{0.0f};  // where rays leaving on the arriving side start
    // Not a stored pointer to `textured`: interactions are copied and must stay valid.
    const SurfaceCoefficients& material() const { return textured ? *textured : *base; }
};

// Builds the surface interactions of a scene's hits.
class SurfaceShading {
  public:
    // `images`: the materials' image textures (null: materials shade with their constant
    // factors); `pixel_spread`: the angle one pixel's samples spread over, radians (the
    // footprint image textures are filtered over, docs/textures.md).
    SurfaceShading(const Accel& accel, const ShadingScene& scene, const ImageTextures* images,
                   float pixel_spread)
        : m_accel(accel), m_scene(scene), m_images(images), m_pixel_spread(pixel_spread) {}

    // Fills `out` for `hit` of `ray` (only the SurfaceInteraction part of a derived record).
    void interact(const Ray& ray, const SurfaceHit& hit, SurfaceInteraction& out) const;

  private:
    // The image footprint's width in texture units at a parameterized hit (Accel::parameterize).
    float texture_width(const SurfaceHit& surface) const;
    // The material's image textures at a parameterized hit, footprint `width`, replacing the
    // coefficients they drive.
    SurfaceCoefficients with_images(const SurfaceHit& surface, float width,
                                    const MaterialImages& images,
                                    SurfaceCoefficients coefficients) const;
    // The glTF metallic-roughness and occlusion images of material `material` at `uv`
    // (`base_texel`: the base colour image's texel there, 1 without one).
    void with_pbr_images(uint32_t material, const PbrImages& pbr, const Vec3& base_texel,
                         const glm::vec2& uv, float width, SurfaceCoefficients& c) const;
    // The shading normal (`normal`, on the arriving side) after the material's normal and bump
    // maps (shading/normal_mapping.h), facing the viewer.
    Vec3 mapped_normal(const SurfaceHit& surface, float width, const MaterialImages& images,
                       bool entering, const Vec3& normal, const Vec3& to_eye) const;

    const Accel& m_accel;
    const ShadingScene& m_scene;
    const ImageTextures* m_images;
    float m_pixel_spread;
};

// Origin of a ray leaving `hit` on the side `side_normal` points to: offset along the
// geometric normal by an amount that scales with the hit position's magnitude and the object's
// size (docs/architecture.md "Numerics": a fixed epsilon fails once coordinates reach ~1e3).
Vec3 offset_ray_origin(const SurfaceHit& hit, const Vec3& side_normal);

}  // namespace rayo
