#pragma once
// Area lights (seed 004: "area lights as sets of point lights"): a rectangle, disk or sphere that
// emits a uniform radiance L = color·intensity from its surface, sampled at `samples` stratified
// points per shading point. The scene loader also puts the surface in the scene as an emissive
// object (apps/scene/area_light_emitters.h) so that camera and reflection rays see it.
#include <memory>
#include <optional>
#include <vector>

#include "core/cdf_guide.h"
#include "core/setting.h"
#include "core/shapes/shape_fields.h"
#include "shading/light_sample.h"
#include "shading/light_text.h"

namespace rayo {

// Most points an area light may be sampled at per shading point (each is a shadow ray): the
// bound of its "samples" field (AreaLight::problem), which the fuzz oracle checks through it.
constexpr int kMaxAreaLightSamples = 4096;

// The emissive triangles of a model (apps/scene/area_light_emitters.h): one light however many
// triangles emit. A sample picks a triangle with probability proportional to its power
// (area × luminance of its radiance: by area when all emit alike), then a uniform point on it,
// so the cost per shading point is the light's `samples` whatever the triangle count; memory is
// one Triangle and one float per emissive triangle. Emission images (glTF emissiveTexture, MTL
// map_Ke) are applied by the integrator at the sampled point (LightSample::emission_material).
class MeshEmitter {
  public:
    struct Triangle {
        Vec3 p0{0.0f}, e1{0.0f}, e2{0.0f};  // p0 + s·e1 + t·e2; emits toward e1 × e2
        Vec3 radiance{0.0f};
        // A material with an emission image: its index (the sample's radiance is `radiance`
        // times the image at the point's texture coordinates), and the coordinates at p0,
        // p0 + e1 and p0 + e2. kNoEmissionImage: `radiance` is uniform.
        uint32_t image_material = kNoEmissionImage;
        glm::vec2 uv0{0.0f}, uv1{0.0f}, uv2{0.0f};
        // Emits on both sides (a two-sided material, shading/material.h), else toward e1 × e2.
        bool two_sided = false;
    };
    // Ignores triangles of zero area or zero radiance. The weight of a triangle in the pick is
    // its area times the luminance of `radiance` (the factor: an emission image is not looked
    // at, so the estimator stays unbiased wherever the image is non-zero).
    void add(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& radiance,
             bool two_sided = false);
    // The same for a triangle whose material `material` has an emission image, with the
    // texture coordinates of a, b, c.
    void add(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& radiance, uint32_t material,
             const glm::vec2& uv_a, const glm::vec2& uv_b, const glm::vec2& uv_c,
             bool two_sided = false);
    bool empty() const { return m_triangles.empty(); }
    size_t size() const { return m_triangles.size(); }
    float area() const { return m_area; }
    const std::vector<Triangle>& triangles() const { return m_triangles; }
    // As AreaLight::sample: uniform u ∈ [0,1)² picks the triangle (u.x, by the power CDF,
    // then rescaled to [0,1) inside the triangle's interval) and the point on it. After
    // finish() the CDF is entered through a guide table (core/cdf_guide.h: expected O(1) per
    // sample, the same triangle as the binary search that is used before it).
    bool sample(const Vec3& point, const glm::vec2& u, LightSample& out) const;
    // Builds the CDF's guide table; called once after the last add (add_mesh_emitter_light).
    // An add after it leaves the table stale, and sample() searches by bisection until the next.
    void finish() { m_guide.build(m_cdf); }
    // The solid-angle density of `direction` under sample (AreaLight::pdf).
    float pdf(const Vec3& point, const Vec3& direction) const;
    // The same for a direction whose first hit `at` is known to be one of the triangles: the
    // pick's wᵢ/W over the area Aᵢ leaves luminance(radiance)/W per unit area, times d²/cos θl,
    // without the search over every triangle that pdf makes.
    float pdf_at(const Vec3& point, const EmitterPoint& at) const;

  private:
    std::vector<Triangle> m_triangles;
    std::vector<float> m_cdf;  // running sum of the weights, m_cdf.back() = total
    CdfGuide m_guide;          // finish()
    float m_area = 0.0f;
};

struct AreaLight {
    static constexpr const char* kName = "area";
    enum class Shape { Rectangle, Disk, Sphere, Mesh };
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
    // Mesh: emissive triangles already in the scene, each with its own radiance (color and
    // intensity unused).
    std::shared_ptr<const MeshEmitter> mesh;

    // The scene file's form (docs/scene-format.md, "lights"): the required "shape" decides which
    // fields() follow, so the scene reader reads form() first (core/shapes/shape_fields.h). A
    // mesh is no form of the file: its triangles come from models' emissive materials.
    template <typename F>
    void form(F& f) {
        f.choice(
            {"shape", "the emitting surface: rectangle, disk or sphere"}, shape,
            {{"rectangle", Shape::Rectangle}, {"disk", Shape::Disk}, {"sphere", Shape::Sphere}});
    }
    // The fields of the form `shape` (a mesh has none of its own), then the common ones.
    template <typename F>
    void fields(F& f) {
        switch (shape) {
            case Shape::Rectangle:
                f("corner", corner, FieldKind::Point);
                f("edge1", edge1, FieldKind::Point);
                f("edge2", edge2, FieldKind::Point);
                break;
            case Shape::Disk:
                f("center", center, FieldKind::Point);
                f("normal", normal, FieldKind::Direction);
                f("radius", radius, FieldKind::Positive);
                break;
            case Shape::Sphere:
                f("center", center, FieldKind::Point);
                f("radius", radius, FieldKind::Positive);
                break;
            case Shape::Mesh:
                break;
        }
        f.optional("samples", samples, FieldKind::Integer);
        f.optional("color", color, FieldKind::Colour);
        f.optional("intensity", intensity, FieldKind::NonNegative);
    }
    // What the fields cannot say alone: samples within [1, kMaxAreaLightSamples], an area that is
    // a positive finite float (parallel edges, a radius whose square underflows), a finite
    // radiance.
    std::optional<FieldProblem> problem() const;

    Vec3 radiance() const { return color * intensity; }  // not for meshes: per triangle
    float area() const;
    // " rectangle|disk|sphere color ... intensity ... area A samples S", a mesh's " mesh
    // triangles N area A samples S".
    void describe(std::ostream& out) const;
    int sample_count() const { return samples; }
    // A point of the light for u ∈ [0,1)² (rectangle and disk: uniform over the area; sphere:
    // uniform over the cone of directions it subtends), as the direction and distance to it, the
    // radiance L and the pdf of the direction per unit solid angle. So L·cos/pdf averaged over
    // the samples is the irradiance the light gives. False when the point sees the light's back
    // (rectangle, disk) or lies inside it (sphere).
    bool sample(const Vec3& point, const glm::vec2& u, LightSample& out) const;
    // The solid-angle density with which sample(point, u) for uniform u gives `direction`
    // (unit), for multiple importance sampling: 0 where it never does (the light missed or seen
    // from behind). Meshes: the sum over the emissive triangles the line crosses.
    static constexpr bool kDelta = false;
    float pdf(const Vec3& point, const Vec3& direction) const;
    // The density for a ray from `point` along `direction` whose first hit `at` lies on this
    // light's surface (a sampling integrator's BSDF ray that found the emitter: its multiple
    // importance weight). Meshes: MeshEmitter::pdf_at; the other shapes: pdf.
    float pdf_at(const Vec3& point, const Vec3& direction, const EmitterPoint& at) const;
    // The radiance a ray along `direction` (unit) carries back from the point `at` of this
    // light's surface where it arrives: L on the emitting side (a mesh: the triangle's own,
    // at.radiance, before any emission image), none from behind (multiple importance sampling
    // weighs it with pdf_at).
    Vec3 emitted(const Vec3& direction, const EmitterPoint& at) const {
        if (!(glm::dot(direction, at.normal) < 0.0f)) return Vec3(0.0f);
        return shape == Shape::Mesh ? at.radiance : radiance();
    }
};

}  // namespace rayo
