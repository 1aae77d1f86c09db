#pragma once
// An Embree instance of a group's scene (core/instance.h) and how to describe its hits: Embree
// traces the group's geometry in object space and reports the instance's id in instID[0], the
// group geometry's in geomID; the group geometry's binding describes the hit in object space and
// this binding carries it to world space (points by M, normals by the inverse transpose of M's
// linear part, renormalised).
#include <embree3/rtcore.h>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <memory>
#include <vector>

#include "core/geometry_binding.h"
#include "core/instance.h"

namespace rayo {

// A group built once: its committed Embree scene and the bindings of its geometries, indexed by
// their geometry id in that scene.
struct GroupScene {
    RTCScene scene = nullptr;
    std::vector<std::unique_ptr<GeometryBinding>> bindings;
    size_t primitive_count = 0;
};

class InstanceBinding : public GeometryBinding {
  public:
    InstanceBinding(const GroupScene& group, const Instance& instance, uint32_t instance_index);

    RTCGeometry geometry() const override { return m_geometry; }
    size_t primitive_count() const override { return m_group.primitive_count; }
    void surface(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& out) const override;
    void parameterize(SurfaceHit& hit) const override;

  private:
    const GroupScene& m_group;
    glm::mat4 m_to_world;
    glm::mat4 m_to_object;
    glm::mat3 m_normal_to_world;  // inverse transpose of the linear part
    float m_size_scale;           // the largest column length: scales object_size
    uint32_t m_material;
    uint32_t m_index;
    RTCGeometry m_geometry = nullptr;
};

}  // namespace rayo
