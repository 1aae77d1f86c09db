#pragma once
// Area lights (seed 004: "area lights as sets of point lights"): a rectangle, disk or sphere that
// emits a uniform radiance L = color·intensity from its surface, sampled at `samples` stratified
// points per shading point. The scene loader also puts the surface in the scene as an emissive
// object (apps/scene/area_light_emitters.h) so that camera and reflection rays see it.
#include "shading/light_sample.h"

namespace rayo {

struct AreaLight {
    enum class Shape { Rectangle, Disk, Sphere };
    Shape shape = Shape::Disk;
    Vec3 color{1.0f};
    float intensity = 1.0f;  // L = color·intensity, the radiance of the emitting surface
    int samples = 16;        // points per shading point (stratified over the light)
    // Rectangle: corner + s·edge1 + t·edge2, s, t ∈ [0, 1]; emits toward edge1 × edge2.
    Vec3 corner{0.0f}, edge1{1.0f, 0.0f, 0.0f}, edge2{0.0f, 0.0f, 1.0f};
    // Disk (emits toward `normal`, unit) and sphere (emits outward).
    Vec3 center{0.0f};
    Vec3 normal{0.0f, -1.0f, 0.0f};
    float radius = 1.0f;

    Vec3 radiance() const { return color * intensity; }
    float area() const;
    int sample_count() const { return samples; }
    // A point of the light for u ∈ [0,1)² (rectangle and disk: uniform over the area; sphere:
    // uniform over the cone of directions it subtends), as the direction and distance to it, the
    // radiance L and the pdf of the direction per unit solid angle. So L·cos/pdf averaged over
    // the samples is the irradiance the light gives. False when the point sees the light's back
    // (rectangle, disk) or lies inside it (sphere).
    bool sample(const Vec3& point, const glm::vec2& u, LightSample& out) const;
};

}  // namespace rayo
