#include "core/instance_binding.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/embree_device.h"

namespace rayo {

static_assert(RTC_MAX_INSTANCE_LEVEL_COUNT >= kMaxInstanceLevels,
              "core/instance.h: this Embree cannot trace the instance levels rayo allows");

InstanceBinding::InstanceBinding(const GroupScene& group, const Instance& instance,
                                 uint32_t instance_index)
    : m_group(group),
      m_to_world(instance.transform),
      m_to_object(glm::inverse(instance.transform)),
      m_normal_to_world(glm::transpose(glm::inverse(glm::mat3(instance.transform)))),
      m_material(instance.material),
      m_index(instance_index) {
    const glm::mat3 linear(instance.transform);
    m_size_scale =
        glm::max(glm::length(linear[0]), glm::max(glm::length(linear[1]), glm::length(linear[2])));
    // Embree's affine transform as 4 columns of 3 floats (the last column the translation).
    float xfm[12];
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 3; ++r) xfm[3 * c + r] = instance.transform[c][r];
    }
    m_geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(m_geometry, group.scene);
    rtcSetGeometryTimeStepCount(m_geometry, 1);
    rtcSetGeometryTransform(m_geometry, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
}

void InstanceBinding::surface(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& out) const {
    // The ray in object space, as Embree traced it: t is the same parameter in both spaces
    // (the direction is mapped, not renormalised).
    Ray local = ray;
    local.origin = Vec3(m_to_object * glm::vec4(ray.origin, 1.0f));
    local.direction = glm::mat3(m_to_object) * ray.direction;
    const uint32_t geometry = rayhit.hit.geomID;
    m_group.bindings[geometry]->surface(local, rayhit, out);
    out.position = Vec3(m_to_world * glm::vec4(out.position, 1.0f));
    out.terminator_offset =
        glm::mat3(m_to_world) * out.terminator_offset;  // a difference of points
    // Normals are covectors: n' = (M⁻¹)ᵀ n keeps them perpendicular to the mapped surface (and
    // outward, for any sign of det M).
    out.geometric_normal = glm::normalize(m_normal_to_world * out.geometric_normal);
    out.shading_normal = glm::normalize(m_normal_to_world * out.shading_normal);
    out.object_size *= m_size_scale;
    if (m_material != kNoMaterialOverride) out.material = m_material;
    out.instance = m_index;
    out.group_geometry = geometry;
}

void InstanceBinding::parameterize(SurfaceHit& hit) const {
    SurfaceHit local = hit;
    local.position = Vec3(m_to_object * glm::vec4(hit.position, 1.0f));
    m_group.bindings[hit.group_geometry]->parameterize(local);
    hit.uv = local.uv;
    hit.dpdu = glm::mat3(m_to_world) * local.dpdu;  // a tangent: mapped by M's linear part
    hit.dpdv = glm::mat3(m_to_world) * local.dpdv;
    // The vertex tangent is a tangent too; a mirror (det M < 0) flips the frame's handedness,
    // since (Ma) × (Mb) = det M · M⁻ᵀ(a × b) while the bitangent maps as M·b.
    const float handedness = glm::determinant(glm::mat3(m_to_world)) < 0.0f ? -1.0f : 1.0f;
    hit.tangent =
        glm::vec4(glm::mat3(m_to_world) * glm::vec3(local.tangent), handedness * local.tangent.w);
}

}  // namespace rayo
