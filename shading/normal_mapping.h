#pragma once
// Image-driven shading normals (docs/models.md, "Normal and bump maps"): tangent-space normal
// maps (glTF normalTexture, MTL norm) and height maps (MTL map_bump/bump, Blinn 1978). Each
// replaces the shading normal only; the geometric normal still decides sides and ray offsets.
#include <glm/vec4.hpp>

#include "core/math.h"

namespace rayo {

// A tangent frame's tangent where the mesh gives none (TriangleMesh::tangents): the hit's
// ∂p/∂u, with the handedness w = ±1 that makes w·(normal × tangent) point up the image, along
// −∂p/∂v (texture coordinates t grow down the image). Zero (w = 0) when ∂p/∂u is zero.
glm::vec4 surface_tangent(const Vec3& normal, const Vec3& dpdu, const Vec3& dpdv);

// The normal a tangent-space normal map gives (glTF 2.0 "normalTexture"): the texel's
// m = (2·rgb − 1)·(scale, scale, 1) in the frame T (the tangent Gram-Schmidt orthogonalised
// against `normal`), B = w·(normal × T), N = `normal` (unit): normalize(m.x·T + m.y·B + m.z·N).
// `normal` itself when the frame or the result is degenerate.
Vec3 tangent_space_normal(const Vec3& normal, const glm::vec4& tangent, const Vec3& texel,
                          float scale);

// Blinn's perturbed normal ("Simulation of Wrinkled Surfaces", SIGGRAPH 1978): the surface
// displaced by the height F along its unit `normal` has the tangents P_u + F_u·N and
// P_v + F_v·N, and the normal N' = (P_u + F_u·N) × (P_v + F_v·N) (Blinn's eq. before dropping
// the F_u·F_v term), on `normal`'s side. P_u, P_v are ∂p/∂u and ∂p/∂v projected onto the
// plane of `normal` (so that a smooth-shaded mesh keeps its interpolated normal where F is
// flat), F_u = ∂F/∂u and F_v = ∂F/∂v. `normal` itself when the tangents are degenerate.
Vec3 bump_mapped_normal(const Vec3& normal, const Vec3& dpdu, const Vec3& dpdv, float dfdu,
                        float dfdv);

// A perturbed normal that faces away from the viewer (`to_eye`, unit, n·v below a small
// cosine) is bent toward the viewer until it faces them: n + (2c₀ − n·v)·v normalised,
// c₀ = kMinBumpCosine (shading/texture.h), as the procedural bump keeps its normal on the
// geometric normal's side. Production renderers do the same (Cycles' ensure_valid_reflection
// is a finer form): a map cannot show the viewer the back of the surface.
Vec3 face_viewer(const Vec3& normal, const Vec3& to_eye);

}  // namespace rayo
