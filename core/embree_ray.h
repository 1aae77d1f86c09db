#pragma once
// rayo's Ray as Embree 3's RTCRay / RTCRayHit, and the context of a stream call: what the accel
// (core/accel.cpp) and the raw-Embree twins of bench/stream_kinds_bench.cpp both hand to Embree.
#include <embree3/rtcore.h>

#include "core/accel.h"
#include "core/ray.h"

namespace rayo {

inline RTCRay make_rtc_ray(const Ray& ray) {
    RTCRay r;
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x;
    r.dir_y = ray.direction.y;
    r.dir_z = ray.direction.z;
    r.tnear = ray.tnear;
    r.tfar = ray.tfar;
    r.time = 0.0f;
    r.mask = 0xFFFFFFFFu;  // Debian's Embree has ray masks on: mask 0 would hit nothing
    r.id = 0;
    r.flags = 0;
    return r;
}

inline RTCRayHit make_rtc_rayhit(const Ray& ray) {
    RTCRayHit rayhit;
    rayhit.ray = make_rtc_ray(ray);
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rayhit;
}

// The context of a stream call: Embree's traversal for coherent or incoherent rays.
inline RTCIntersectContext stream_context(Accel::Coherence coherence) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = coherence == Accel::Coherence::Coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                                            : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    return context;
}

}  // namespace rayo
