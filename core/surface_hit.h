#pragma once
// What the shader needs to know about the nearest hit: filled by the shape that was hit
// (core/shapes/shape.h) through the accel.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/math.h"

namespace rayo {

constexpr uint32_t kNoInstance = 0xFFFFFFFFu;

struct SurfaceHit {
    float t = 0.0f;
    Vec3 position{0.0f};          // on the surface (sphere hits re-projected onto the sphere)
    Vec3 geometric_normal{0.0f};  // unit, outward (analytic shapes) or by winding (triangles)
    Vec3 shading_normal{0.0f};    // unit, interpolated where the mesh has normals; same side as Ng
    // Smooth-shaded triangles: from `position` to where shadow rays leaving the geometric
    // normal's side start (core/shadow_terminator.h); zero for every other surface.
    Vec3 terminator_offset{0.0f};
    // The mesh's interpolated vertex colour (TriangleMesh::colors); 1 for every other surface.
    Vec3 vertex_color{1.0f};
    float object_size = 0.0f;  // radius or extent: scales the spawned-ray offset
    uint32_t material = 0;
    uint32_t shape = 0;      // the shape type: its index in AnalyticShapes, or kTriangleShape
    uint32_t primitive = 0;  // index of the shape within its type, or of the triangle in its mesh
    uint32_t mesh = 0;       // the mesh's index, for triangles
    uint32_t geometry = 0;   // the accel's Embree geometry id (an instance's, for instanced hits)
    // For hits through an instance (core/instance.h): the instance's index in Scene::instances
    // and the geometry id within its group's Embree scene; shape, primitive and mesh then refer
    // to the group's objects. kNoInstance for everything placed directly.
    uint32_t instance = kNoInstance;
    uint32_t group_geometry = 0;
    // Surface parameterization, filled on request only (Accel::parameterize: image textures ask
    // for it; the sphere's costs an atan2 and an acos). Meshes with texture coordinates give
    // them interpolated, and both tangents ∂p/∂u, ∂p/∂v; other surfaces leave dpdv zero.
    glm::vec2 uv{0.0f};
    Vec3 dpdu{0.0f};
    Vec3 dpdv{0.0f};
    // The mesh's interpolated vertex tangent (TriangleMesh::tangents: xyz, w = ±1 handedness),
    // filled by Accel::parameterize where all three corners have one; zero otherwise.
    glm::vec4 tangent{0.0f};
};

}  // namespace rayo
