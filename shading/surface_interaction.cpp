#include "shading/surface_interaction.h"

#include <algorithm>
#include <cmath>

#include "core/luminance.h"
#include "shading/metallic_roughness.h"
#include "shading/normal_mapping.h"
#include "shading/texture.h"

namespace rayo {
namespace {

// The texture of index `id`, or null for kNoTexture (render_scene has checked the ids).
const Texture* texture_at(const std::vector<Texture>& textures, int32_t id) {
    return id == kNoTexture ? nullptr : &textures[static_cast<size_t>(id)];
}

// The effective coefficients of a textured material at `position` (seed 003 ch. 3): each textured
// ka/kd/ks replaced by its texture's colour there.
SurfaceCoefficients material_at(const Material& m, const std::vector<Texture>& textures,
                                const Vec3& position) {
    SurfaceCoefficients local = m;
    const Texture* ka = texture_at(textures, m.textures.ka);
    const Texture* kd = texture_at(textures, m.textures.kd);
    const Texture* ks = texture_at(textures, m.textures.ks);
    if (kd) local.kd = kd->color(position);
    // ka often shares kd's texture (the default ka = 0.1 × kd): evaluate it once.
    if (ka) local.ka = m.textures.ka_scale * (ka == kd ? local.kd : ka->color(position));
    if (ks) local.ks = ks->color(position);
    return local;
}

}  // namespace

Vec3 offset_ray_origin(const SurfaceHit& hit, const Vec3& side_normal) {
    // eps = max(|P|∞, t, size)·k: about 80 float ulps of the largest magnitude involved, so the
    // new ray cannot re-hit the surface it leaves however far from the origin it lies.
    constexpr float kRelativeOffset = 1e-5f;
    const float scale = glm::max(max_abs_component(hit.position), glm::max(hit.t, hit.object_size));
    return hit.position + (kRelativeOffset * glm::max(scale, 1e-3f)) * side_normal;
}

void SurfaceShading::interact(const Ray& ray, const SurfaceHit& hit, SurfaceInteraction& p) const {
    const Material& base = m_scene.materials[hit.material];
    // Which side the ray arrived on: seed 000 flips the normal for hits from inside (t1).
    p.entering = glm::dot(ray.direction, hit.geometric_normal) < 0.0f;
    p.facing_geometric = p.entering ? hit.geometric_normal : -hit.geometric_normal;
    p.normal = p.entering ? hit.shading_normal : -hit.shading_normal;
    p.base = &base;
    // The path integrator fills one interaction per vertex in turn: an untextured hit after a
    // textured one must not keep that one's coefficients (the ground under a textured glTF
    // model reflected the model's base colour into its bounce light; docs/path-tracing.md,
    // "Against Cycles").
    p.textured.reset();
    // Procedural textures (seed 003 ch. 3): untextured materials skip this and are used as is.
    if (base.textures.any()) {
        p.textured = material_at(base, m_scene.textures, hit.position);
        if (const Texture* bump = texture_at(m_scene.textures, base.textures.bump)) {
            p.normal = bump_normal(*bump, base.textures.bump_strength, hit.position, p.normal,
                                   p.facing_geometric);
        }
    }
    if (m_images && base.images.any()) {
        SurfaceHit surface = hit;
        m_accel.parameterize(surface);
        const float width = texture_width(surface);
        p.textured = with_images(surface, width, base.images, p.material());
        if (base.images.normal.used() || base.images.bump.used()) {
            p.normal =
                mapped_normal(surface, width, base.images, p.entering, p.normal, -ray.direction);
        }
    }
    if (hit.vertex_color != Vec3(1.0f)) {
        // Vertex colours multiply the (textured) diffuse and ambient colours.
        SurfaceCoefficients coloured = p.material();
        coloured.kd *= hit.vertex_color;
        coloured.ka *= hit.vertex_color;
        coloured.metallic_roughness.base_color *= hit.vertex_color;
        p.textured = coloured;
    }
    p.to_eye = -ray.direction;
    p.shadow_origin = offset_ray_origin(hit, p.facing_geometric);
}

float SurfaceShading::texture_width(const SurfaceHit& surface) const {
    // The footprint: the pixel's spread at the hit's distance, in texture units through the
    // surface's tangents (isotropic: the geometric mean of the two scales).
    const float world = m_pixel_spread * surface.t;
    const float du = glm::length(surface.dpdu), dv = glm::length(surface.dpdv);
    const float scale = dv > 0.0f ? std::sqrt(du * dv) : du;
    return scale > 0.0f ? world / scale : 0.0f;
}

Vec3 SurfaceShading::mapped_normal(const SurfaceHit& surface, float width,
                                   const MaterialImages& images, bool entering, const Vec3& normal,
                                   const Vec3& to_eye) const {
    using Slot = ImageTextures::Slot;
    // The maps' frames are the surface's: work with the normal on the geometric normal's side.
    const float side = entering ? 1.0f : -1.0f;
    Vec3 n = side * normal;
    if (m_images->has(surface.material, Slot::Normal)) {
        const glm::vec4 tangent = surface.tangent.w != 0.0f
                                      ? surface.tangent
                                      : surface_tangent(n, surface.dpdu, surface.dpdv);
        const Vec3 texel(m_images->lookup(surface.material, Slot::Normal, surface.uv, width));
        n = tangent_space_normal(n, tangent, texel, images.normal_scale);
    }
    if (m_images->has(surface.material, Slot::Bump)) {
        // F = bump_scale × the height's luminance; ∂F/∂u, ∂F/∂v by forward differences over
        // half the footprint (a small fixed step when it is zero), as pbrt 3 does (9.3).
        const float step = width > 0.0f ? 0.5f * width : 0.0005f;
        const auto height = [&](const glm::vec2& uv) {
            const glm::vec4 texel = m_images->lookup(surface.material, Slot::Bump, uv, width);
            return images.bump_scale * luminance(Vec3(texel));
        };
        const float f = height(surface.uv);
        const float dfdu = (height(surface.uv + glm::vec2(step, 0.0f)) - f) / step;
        const float dfdv = (height(surface.uv + glm::vec2(0.0f, step)) - f) / step;
        n = bump_mapped_normal(n, surface.dpdu, surface.dpdv, dfdu, dfdv);
    }
    return face_viewer(side * n, to_eye);
}

SurfaceCoefficients SurfaceShading::with_images(const SurfaceHit& surface, float width,
                                                const MaterialImages& images,
                                                SurfaceCoefficients c) const {
    using Slot = ImageTextures::Slot;
    Vec3 base_texel(1.0f);
    if (m_images->has(surface.material, Slot::Base)) {
        const Vec3 texel(m_images->lookup(surface.material, Slot::Base, surface.uv, width));
        if (images.ka.used) c.ka = images.ka.apply(texel);
        if (images.kd.used) c.kd = images.kd.apply(texel);
        if (images.ks.used) c.ks = images.ks.apply(texel);
        if (images.reflect.used) c.reflect = images.reflect.apply(texel);
        // The physically based parameters follow the base colour image too (material_bsdf.h).
        if (c.metallic_roughness.used) c.metallic_roughness.base_color *= texel;
        base_texel = texel;
    }
    if (images.pbr.used())
        with_pbr_images(surface.material, images.pbr, base_texel, surface.uv, width, c);
    if (m_images->has(surface.material, Slot::Specular)) {
        c.ks *= Vec3(m_images->lookup(surface.material, Slot::Specular, surface.uv, width));
    }
    if (m_images->has(surface.material, Slot::Emission)) {
        c.emission *= Vec3(m_images->lookup(surface.material, Slot::Emission, surface.uv, width));
    }
    return c;
}

void SurfaceShading::with_pbr_images(uint32_t material, const PbrImages& pbr,
                                     const Vec3& base_texel, const glm::vec2& uv, float width,
                                     SurfaceCoefficients& c) const {
    using Slot = ImageTextures::Slot;
    if (m_images->has(material, Slot::MetallicRoughness)) {
        // glTF 2.0 (3.9.2): metalness in B, roughness in G, linear, times the factors; the
        // metallic workflow redone with the hit's base colour (shading/metallic_roughness.h).
        const glm::vec4 t = m_images->lookup(material, Slot::MetallicRoughness, uv, width);
        const float metallic = pbr.metallic_factor * std::clamp(t.z, 0.0f, 1.0f);
        const float roughness = pbr.roughness_factor * std::clamp(t.y, 0.0f, 1.0f);
        apply_metallic_roughness(c, pbr.base_factor * base_texel, metallic, roughness);
    }
    if (m_images->has(material, Slot::Occlusion)) {
        // glTF occlusion (R, linear) darkens the ambient term only: direct light is shadowed by
        // shadow rays already.
        const float occlusion = m_images->lookup(material, Slot::Occlusion, uv, width).x;
        c.ka *= occlusion_factor(std::clamp(occlusion, 0.0f, 1.0f), pbr.occlusion_strength);
    }
}

}  // namespace rayo
