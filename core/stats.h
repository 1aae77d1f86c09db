#pragma once
// Ray statistics, counted per thread without sharing and merged after the render
// (docs/architecture.md "Hot-path rules").
#include <cstdint>

namespace rayo {

struct RayCounters {
    uint64_t camera = 0;
    uint64_t camera_hits = 0;  // camera rays that hit a surface (the SPD's "eye hit rays")
    uint64_t shadow = 0;
    uint64_t shadow_filtered = 0;  // filtered shadows: rays continued past a transmissive surface
    uint64_t reflection = 0;
    uint64_t refraction = 0;
    uint64_t total_internal_reflections = 0;
    uint64_t depth_cut = 0;         // paths stopped by the maximum depth
    uint64_t contribution_cut = 0;  // paths stopped by the minimum-contribution threshold
    // Thread-seconds inside the accel's stream calls (traversal and hit records), by kind, where
    // the integrator times them (the path wavefront; 0 elsewhere): the rays of a kind over its
    // seconds are that kind's rate per thread (`--stats`).
    double camera_trace_seconds = 0.0;
    double bounce_trace_seconds = 0.0;  // the reflected and refracted rays
    double shadow_trace_seconds = 0.0;

    uint64_t total_rays() const {
        return camera + shadow + shadow_filtered + reflection + refraction;
    }
    RayCounters& operator+=(const RayCounters& o) {
        camera += o.camera;
        camera_hits += o.camera_hits;
        shadow += o.shadow;
        shadow_filtered += o.shadow_filtered;
        reflection += o.reflection;
        refraction += o.refraction;
        total_internal_reflections += o.total_internal_reflections;
        depth_cut += o.depth_cut;
        contribution_cut += o.contribution_cut;
        camera_trace_seconds += o.camera_trace_seconds;
        bounce_trace_seconds += o.bounce_trace_seconds;
        shadow_trace_seconds += o.shadow_trace_seconds;
        return *this;
    }
};

}  // namespace rayo
