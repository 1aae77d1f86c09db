#pragma once
// The one generic pair of Embree user-geometry callbacks, templated on the shape's intersector
// (core/shapes/shape.h), and the binding that attaches any Shape type as Embree user geometry.
// Written for any N: rtcIntersect1 calls them with N = 1, packets and streams with 4/8/16; per
// lane data goes through the RTCRayN_/RTCHitN_ accessors (Embree 3 user-geometry API).
#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "core/embree_device.h"
#include "core/geometry_binding.h"
#include "core/shapes/shape.h"

namespace rayo {

// How a callback asks an intersector for its nearest hit: `nearest()` by default; spheres pass
// one that names the math (core/shapes/sphere_geometry.h).
struct CallNearest {
    template <typename I>
    static bool run(const I& shape, const Vec3& origin, const Vec3& direction, float tnear,
                    float tfar, ShapeHit& hit) {
        return shape.nearest(origin, direction, tnear, tfar, hit);
    }
};

template <typename S>
struct UserGeometryData {
    const S* shapes = nullptr;
    const typename ShapeTraits<S>::Intersector* intersectors = nullptr;
};

template <typename RayN>
inline void read_ray_lane(RayN* ray, unsigned n, unsigned i, Vec3& origin, Vec3& direction) {
    origin = Vec3(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i));
    direction = Vec3(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i));
}

// Inside an instance Embree hands the callbacks the ray in the group's object space
// (core/instance.h), where a scaled instance makes the direction non-unit; shapes take unit
// directions (core/shapes/shape.h). Returns the direction's length when it must be renormalised
// (t then scales by it), 1 otherwise: outside instances, and where the mapping kept the length
// to float rounding (identity, rotations), so that those rays take the shapes' path unchanged.
inline float instanced_direction_length(const RTCIntersectContext* context, const Vec3& d) {
    if (context->instID[0] == RTC_INVALID_GEOMETRY_ID) return 1.0f;
    const float length_squared = glm::dot(d, d);
    return std::abs(length_squared - 1.0f) <= 1e-6f ? 1.0f : std::sqrt(length_squared);
}

template <typename S>
void user_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* data = static_cast<const UserGeometryData<S>*>(args->geometryUserPtr);
    const Bounds3 b = data->shapes[args->primID].bounds();
    RTCBounds* out = args->bounds_o;
    out->lower_x = b.lower.x;
    out->lower_y = b.lower.y;
    out->lower_z = b.lower.z;
    out->upper_x = b.upper.x;
    out->upper_y = b.upper.y;
    out->upper_z = b.upper.z;
}

template <typename S, typename Call = CallNearest>
void user_intersect(const RTCIntersectFunctionNArguments* args) {
    const auto* data = static_cast<const UserGeometryData<S>*>(args->geometryUserPtr);
    const auto& shape = data->intersectors[args->primID];
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    const unsigned n = args->N;
    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] == 0) continue;
        Vec3 origin, direction;
        read_ray_lane(ray, n, i, origin, direction);
        float tnear = RTCRayN_tnear(ray, n, i), tfar = RTCRayN_tfar(ray, n, i);
        const float length = instanced_direction_length(args->context, direction);
        if (length != 1.0f) {
            direction /= length;
            tnear *= length;
            tfar *= length;
        }
        ShapeHit h;
        if (!Call::run(shape, origin, direction, tnear, tfar, h)) continue;
        if (length != 1.0f) {
            h.t /= length;
            if (!(h.t < RTCRayN_tfar(ray, n, i))) continue;  // rounding of the rescale
        }
        RTCRayN_tfar(ray, n, i) = h.t;
        RTCHitN_Ng_x(hit, n, i) = h.normal.x;
        RTCHitN_Ng_y(hit, n, i) = h.normal.y;
        RTCHitN_Ng_z(hit, n, i) = h.normal.z;
        RTCHitN_u(hit, n, i) = 0.0f;
        RTCHitN_v(hit, n, i) = 0.0f;
        RTCHitN_primID(hit, n, i) = args->primID + h.part;
        RTCHitN_geomID(hit, n, i) = args->geomID;
        RTCHitN_instID(hit, n, i, 0) = args->context->instID[0];
    }
}

template <typename S, typename Call = CallNearest>
void user_occluded(const RTCOccludedFunctionNArguments* args) {
    const auto* data = static_cast<const UserGeometryData<S>*>(args->geometryUserPtr);
    const auto& shape = data->intersectors[args->primID];
    const unsigned n = args->N;
    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] == 0) continue;
        Vec3 origin, direction;
        read_ray_lane(args->ray, n, i, origin, direction);
        float tnear = RTCRayN_tnear(args->ray, n, i), tfar = RTCRayN_tfar(args->ray, n, i);
        const float length = instanced_direction_length(args->context, direction);
        if (length != 1.0f) {
            direction /= length;
            tnear *= length;
            tfar *= length;
        }
        ShapeHit h;
        if (Call::run(shape, origin, direction, tnear, tfar, h)) {
            RTCRayN_tfar(args->ray, n, i) = -std::numeric_limits<float>::infinity();
        }
    }
}

// A user geometry of `count` primitives of type S traced by the generic callbacks above, their
// data at `data` (Embree 3 ignores the bounds function's own pointer: the data goes through
// rtcSetGeometryUserData).
template <typename S, typename Call = CallNearest>
RTCGeometry new_user_geometry(unsigned count, UserGeometryData<S>* data) {
    RTCGeometry geometry = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, count);
    rtcSetGeometryUserData(geometry, data);
    rtcSetGeometryBoundsFunction(geometry, user_bounds<S>, nullptr);
    rtcSetGeometryIntersectFunction(geometry, user_intersect<S, Call>);
    rtcSetGeometryOccludedFunction(geometry, user_occluded<S, Call>);
    return geometry;
}

// The surfaces of hits on shapes of type S whose Embree primitive id is the shape's index: the
// base of every binding of a Shape type (user geometry here; Embree's own point spheres and the
// brute-force aggregate in core/shapes/sphere_geometry.cpp). Derived classes create m_geometry.
template <typename S>
class ShapeSurfaceBinding : public GeometryBinding {
  public:
    ShapeSurfaceBinding(const std::vector<S>& shapes, uint32_t shape_index)
        : m_shapes(shapes), m_shape_index(shape_index) {}

    RTCGeometry geometry() const override { return m_geometry; }
    size_t primitive_count() const override { return m_shapes.size(); }
    void surface(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& out) const override {
        const uint32_t prim = rayhit.hit.primID;
        const S& shape = m_shapes[prim];
        const ShapeHit hit{rayhit.ray.tfar,
                           Vec3(rayhit.hit.Ng_x, rayhit.hit.Ng_y, rayhit.hit.Ng_z)};
        out.t = hit.t;
        shape.surface(ray, hit, out);
        out.material = shape.material;
        out.shape = m_shape_index;
        out.primitive = prim;
    }
    void parameterize(SurfaceHit& hit) const override {
        m_shapes[hit.primitive].parameterization(hit.position, hit);
    }

  protected:
    const std::vector<S>& m_shapes;
    uint32_t m_shape_index;
    RTCGeometry m_geometry = nullptr;
};

// Any Shape S as Embree user geometry: one primitive per shape, the generic callbacks above.
template <typename S, typename Call = CallNearest>
class ShapeBinding : public ShapeSurfaceBinding<S> {
  public:
    ShapeBinding(const std::vector<S>& shapes, uint32_t shape_index)
        : ShapeSurfaceBinding<S>(shapes, shape_index) {
        m_data.shapes = shapes.data();
        if constexpr (ShapeTraits<S>::kSelfIntersecting) {
            m_data.intersectors = shapes.data();
        } else {
            m_intersectors.reserve(shapes.size());
            for (const S& s : shapes) m_intersectors.push_back(s.intersector());
            m_data.intersectors = m_intersectors.data();
        }
        this->m_geometry =
            new_user_geometry<S, Call>(static_cast<unsigned>(shapes.size()), &m_data);
    }

  private:
    std::vector<typename ShapeTraits<S>::Intersector> m_intersectors;  // when S names one
    UserGeometryData<S> m_data;
};

// One object of type G as one Embree user primitive through the generic callbacks (a height
// field, a voxel grid: objects that hold a grid and walk it, docs/heightfields.md,
// docs/voxels.md). The hit's `part` travels as the primitive id and its normal as Ng;
// SurfaceHit::mesh gets the object's index, SurfaceHit::shape its type; `primitives` is what
// the object counts for (a height field's triangles).
template <typename G>
class ObjectBinding : public GeometryBinding {
  public:
    ObjectBinding(const G& object, uint32_t object_index, uint32_t shape_index, size_t primitives)
        : m_object(object),
          m_object_index(object_index),
          m_shape_index(shape_index),
          m_primitives(primitives) {
        m_data.shapes = &object;
        m_data.intersectors = &object;
        m_geometry = new_user_geometry<G>(1, &m_data);
    }
    RTCGeometry geometry() const override { return m_geometry; }
    size_t primitive_count() const override { return m_primitives; }
    void surface(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& out) const override {
        ShapeHit hit;
        hit.t = rayhit.ray.tfar;
        hit.normal = Vec3(rayhit.hit.Ng_x, rayhit.hit.Ng_y, rayhit.hit.Ng_z);
        hit.part = rayhit.hit.primID;  // user_intersect reports primitive 0 + part
        out.t = hit.t;
        m_object.surface(ray, hit, out);
        out.material = m_object.material;
        out.shape = m_shape_index;
        out.primitive = hit.part;
        out.mesh = m_object_index;
    }
    void parameterize(SurfaceHit& hit) const override {
        m_object.parameterization(hit.position, hit);
    }

  private:
    const G& m_object;
    uint32_t m_object_index;
    uint32_t m_shape_index;
    size_t m_primitives;
    UserGeometryData<G> m_data;
    RTCGeometry m_geometry = nullptr;
};

// The default binding of a shape type: user geometry. A shape type with other representations
// overloads make_binding for its vector type (spheres: core/shapes/sphere_geometry.h).
struct AccelOptions;
template <typename S>
std::unique_ptr<GeometryBinding> make_binding(const std::vector<S>& shapes, uint32_t shape_index,
                                              const AccelOptions& /*options*/) {
    return std::make_unique<ShapeBinding<S>>(shapes, shape_index);
}

}  // namespace rayo
