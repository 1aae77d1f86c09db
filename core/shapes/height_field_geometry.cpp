#include "core/shapes/height_field_geometry.h"

#include "core/user_geometry.h"

namespace rayo {
namespace {

class HeightFieldBinding : public GeometryBinding {
  public:
    HeightFieldBinding(const HeightField& field, uint32_t field_index, uint32_t shape_index)
        : m_field(field), m_field_index(field_index), m_shape_index(shape_index) {
        m_data.shapes = &field;
        m_data.intersectors = &field;
        m_geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(m_geometry, 1);
        rtcSetGeometryUserData(m_geometry, &m_data);
        rtcSetGeometryBoundsFunction(m_geometry, user_bounds<HeightField>, nullptr);
        rtcSetGeometryIntersectFunction(m_geometry, user_intersect<HeightField>);
        rtcSetGeometryOccludedFunction(m_geometry, user_occluded<HeightField>);
    }
    RTCGeometry geometry() const override { return m_geometry; }
    size_t primitive_count() const override { return m_field.cell_count() * 2; }
    void surface(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& out) const override {
        ShapeHit hit;
        hit.t = rayhit.ray.tfar;
        hit.part = rayhit.hit.primID;  // user_intersect reports primitive 0 + part
        out.t = hit.t;
        m_field.surface(ray, hit, out);
        out.material = m_field.material;
        out.shape = m_shape_index;
        out.primitive = hit.part;
        out.mesh = m_field_index;
    }
    void parameterize(SurfaceHit& hit) const override {
        m_field.parameterization(hit.position, hit);
    }

  private:
    const HeightField& m_field;
    uint32_t m_field_index;
    uint32_t m_shape_index;
    UserGeometryData<HeightField> m_data;
    RTCGeometry m_geometry = nullptr;
};

}  // namespace

std::unique_ptr<GeometryBinding> make_height_field_binding(const HeightField& field,
                                                           uint32_t field_index,
                                                           uint32_t shape_index) {
    return std::make_unique<HeightFieldBinding>(field, field_index, shape_index);
}

}  // namespace rayo
