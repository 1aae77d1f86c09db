#pragma once
// One Embree geometry of an Accel and how to describe its hits. The accel keeps one binding per
// Embree geometry id; after traversal, the nearest hit's binding fills the SurfaceHit (one
// indirect call per hit, none per candidate: the per-candidate code is the templated Embree
// callbacks of core/user_geometry.h).
#include <embree3/rtcore.h>

#include <cstddef>

#include "core/ray.h"
#include "core/surface_hit.h"

namespace rayo {

class GeometryBinding {
  public:
    virtual ~GeometryBinding() = default;
    // The geometry to attach (created, not yet committed); the accel commits and owns it.
    virtual RTCGeometry geometry() const = 0;
    virtual size_t primitive_count() const = 0;
    // The surface of the hit that Embree reported in `rayhit` (t in rayhit.ray.tfar).
    virtual void surface(const Ray& ray, const RTCRayHit& rayhit, SurfaceHit& out) const = 0;
    // uv and dpdu of a hit this binding filled (SurfaceHit: on request only).
    virtual void parameterize(SurfaceHit& hit) const = 0;
};

}  // namespace rayo
