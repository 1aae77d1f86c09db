#include "shading/area_light.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/luminance.h"
#include "core/sampling.h"

namespace rayo {
namespace {

// Two unit vectors completing the unit `w` to an orthonormal basis (Duff et al. 2017,
// "Building an orthonormal basis, revisited").
void basis(const Vec3& w, Vec3& t, Vec3& b) {
    const float sign = std::copysign(1.0f, w.z);
    const float a = -1.0f / (sign + w.z);
    const float c = w.x * w.y * a;
    t = Vec3(1.0f + sign * w.x * w.x * a, sign * c, -sign * w.x);
    b = Vec3(c, sign + w.y * w.y * a, -w.y);
}

// A point `target` of a flat emitter of area `area` and unit normal `normal` seen from `point`:
// the solid-angle pdf of uniform area sampling is d²/(A·cos θl), θl the angle at the light. A
// two-sided emitter (a triangle of a two-sided material, shading/material.h) is seen from both.
bool flat_sample(const Vec3& point, const Vec3& target, const Vec3& normal, float area,
                 const Vec3& radiance, LightSample& out, bool two_sided = false) {
    const Vec3 offset = target - point;
    const float distance = glm::length(offset);
    if (!(distance > 0.0f)) return false;
    out.direction = offset / distance;
    float cos_light = -glm::dot(normal, out.direction);
    if (two_sided) cos_light = std::abs(cos_light);
    if (!(cos_light > 0.0f)) return false;  // the back of a one-sided emitter
    out.distance = distance;
    out.radiance = radiance;
    out.pdf = distance * distance / (area * cos_light);
    out.on_surface = true;
    return true;
}

}  // namespace

void MeshEmitter::add(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& radiance,
                      bool two_sided) {
    add(a, b, c, radiance, kNoEmissionImage, glm::vec2(0.0f), glm::vec2(0.0f), glm::vec2(0.0f),
        two_sided);
}

void MeshEmitter::add(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& radiance,
                      uint32_t material, const glm::vec2& uv_a, const glm::vec2& uv_b,
                      const glm::vec2& uv_c, bool two_sided) {
    const Triangle t{a, b - a, c - a, radiance, material, uv_a, uv_b, uv_c, two_sided};
    const float area = 0.5f * glm::length(glm::cross(t.e1, t.e2));
    const float weight = area * luminance(radiance);
    if (!(area > 0.0f) || !(weight > 0.0f) || !std::isfinite(weight)) return;
    m_triangles.push_back(t);
    m_cdf.push_back((m_cdf.empty() ? 0.0f : m_cdf.back()) + weight);
    m_area += area;
}

bool MeshEmitter::sample(const Vec3& point, const glm::vec2& u, LightSample& out) const {
    if (m_triangles.empty()) return false;
    // Triangle i with probability wᵢ/W: the first running sum above u.x·W.
    const float total = m_cdf.back();
    const float target = u.x * total;
    const size_t i = std::min<size_t>(m_guide.find(m_cdf, u.x, target), m_cdf.size() - 1);
    const float low = i == 0 ? 0.0f : m_cdf[i - 1];
    const float weight = m_cdf[i] - low;
    const float v = std::clamp((target - low) / weight, 0.0f, 0.99999994f);
    // A uniform point of the triangle (Shirley's square-to-triangle map: √v, then u.y along the
    // far edge), area pdf 1/Aᵢ; with the pick, the area pdf is wᵢ/(W·Aᵢ) = 1/A_eff.
    const Triangle& t = m_triangles[i];
    const float s = std::sqrt(v);
    const float b1 = s * (1.0f - u.y), b2 = s * u.y;
    const Vec3 target_point = t.p0 + b1 * t.e1 + b2 * t.e2;
    const Vec3 cross = glm::cross(t.e1, t.e2);
    const float cross_length = glm::length(cross);
    const float triangle_area = 0.5f * cross_length;
    const float effective_area = triangle_area * total / weight;
    if (!flat_sample(point, target_point, cross / cross_length, effective_area, t.radiance, out,
                     t.two_sided)) {
        return false;
    }
    if (t.image_material != kNoEmissionImage) {
        out.emission_material = t.image_material;
        out.uv = t.uv0 + b1 * (t.uv1 - t.uv0) + b2 * (t.uv2 - t.uv0);
    }
    return true;
}

void AreaLight::describe(std::ostream& out) const {
    static const char* const kShapes[] = {"rectangle", "disk", "sphere", "mesh"};
    out << " " << kShapes[static_cast<int>(shape)];
    if (mesh) {
        out << " triangles " << mesh->size();
    } else {
        write_color_and_intensity(out, color, intensity);
    }
    out << " area " << area() << " samples " << samples;
}

std::optional<FieldProblem> AreaLight::problem() const {
    if (samples < 1 || samples > kMaxAreaLightSamples) {
        return FieldProblem{"samples", "expected an integer in [1, " +
                                           std::to_string(kMaxAreaLightSamples) + "], got " +
                                           std::to_string(samples)};
    }
    const float a = area();
    if (!(a > 0.0f) || !std::isfinite(a)) {
        switch (shape) {
            case Shape::Rectangle:
                return FieldProblem{"edge2",
                                    "expected edge1 and edge2 to span a rectangle of non-zero "
                                    "area (not parallel, neither zero)"};
            case Shape::Disk:
            case Shape::Sphere:
                return FieldProblem{"radius", "expected a radius whose area is a positive float"};
            case Shape::Mesh:
                return FieldProblem{"shape", "expected emitting triangles of non-zero area"};
        }
    }
    const Vec3 l = radiance();
    if (!std::isfinite(l.x) || !std::isfinite(l.y) || !std::isfinite(l.z)) {
        return FieldProblem{"intensity", "expected color × intensity to be finite"};
    }
    return std::nullopt;
}

float AreaLight::area() const {
    switch (shape) {
        case Shape::Mesh:
            return mesh ? mesh->area() : 0.0f;
        case Shape::Rectangle:
            return glm::length(glm::cross(edge1, edge2));
        case Shape::Disk:
            return kPi * radius * radius;
        case Shape::Sphere:
            break;
    }
    return 4.0f * kPi * radius * radius;
}

bool AreaLight::sample(const Vec3& point, const glm::vec2& u, LightSample& out) const {
    switch (shape) {
        case Shape::Mesh:
            return mesh && mesh->sample(point, u, out);
        case Shape::Rectangle:
            return flat_sample(point, corner + u.x * edge1 + u.y * edge2,
                               unit_vector(glm::cross(edge1, edge2)), area(), radiance(), out);
        case Shape::Disk: {
            Vec3 t, b;
            basis(normal, t, b);
            const glm::vec2 d = radius * concentric_disk(u);
            return flat_sample(point, center + d.x * t + d.y * b, normal, area(), radiance(), out);
        }
        case Shape::Sphere:
            break;
    }
    // Sphere: uniform over the cone toward it, half-angle θmax with sin θmax = r/dc (the visible
    // cap only, no sample wasted on the far side); pdf = 1/(2π(1 − cos θmax)).
    const Vec3 to_center = center - point;
    const float dc = glm::length(to_center);
    if (!(dc > radius)) return false;
    const float sin2_max = (radius / dc) * (radius / dc);
    // 1 − cos θmax = 1 − √(1 − s²) = s²/(1 + √(1 − s²)): no cancellation for small lights.
    const float one_minus_cos_max = sin2_max / (1.0f + std::sqrt(1.0f - sin2_max));
    const float cos_theta = 1.0f - u.x * one_minus_cos_max;
    const float sin_theta = std::sqrt(glm::max(0.0f, 1.0f - cos_theta * cos_theta));
    const float phi = 2.0f * kPi * u.y;
    const Vec3 w = to_center / dc;
    Vec3 t, b;
    basis(w, t, b);
    out.direction =
        glm::normalize(cos_theta * w + sin_theta * (std::cos(phi) * t + std::sin(phi) * b));
    // The nearer crossing of the sphere along the direction (b = d·(c − p) > 0 inside the cone).
    const float along = glm::dot(out.direction, to_center);
    const Vec3 perpendicular = to_center - along * out.direction;
    const float half_chord2 =
        glm::max(0.0f, radius * radius - glm::dot(perpendicular, perpendicular));
    out.distance = along - std::sqrt(half_chord2);
    out.radiance = radiance();
    out.pdf = 1.0f / (2.0f * kPi * one_minus_cos_max);
    out.on_surface = true;
    return true;
}

}  // namespace rayo

namespace rayo {
namespace {

// The density d²/(A·cos θl) of a flat emitter's point `hit` (on its front, or either side when
// two-sided) seen along `direction` from `point`, or 0 from behind (flat_sample's pdf).
float flat_pdf(const Vec3& point, const Vec3& hit, const Vec3& normal, float area,
               const Vec3& direction, bool two_sided = false) {
    float cos_light = -glm::dot(normal, direction);
    if (two_sided) cos_light = std::abs(cos_light);
    if (!(cos_light > 0.0f) || !(area > 0.0f)) return 0.0f;
    const Vec3 offset = hit - point;
    return glm::dot(offset, offset) / (area * cos_light);
}

// Where the ray point + t·direction (t > 0) meets the plane through `origin` with normal `n`.
bool plane_crossing(const Vec3& point, const Vec3& direction, const Vec3& origin, const Vec3& n,
                    Vec3& hit) {
    const float denominator = glm::dot(direction, n);
    if (denominator == 0.0f) return false;
    const float t = glm::dot(origin - point, n) / denominator;
    if (!(t > 0.0f)) return false;
    hit = point + t * direction;
    return true;
}

}  // namespace

float MeshEmitter::pdf(const Vec3& point, const Vec3& direction) const {
    if (m_triangles.empty()) return 0.0f;
    const float total = m_cdf.back();
    float density = 0.0f;
    for (size_t i = 0; i < m_triangles.size(); ++i) {
        const Triangle& t = m_triangles[i];
        // Möller–Trumbore: the line's crossing of the triangle, if any, in front of the point.
        const Vec3 p = glm::cross(direction, t.e2);
        const float det = glm::dot(t.e1, p);
        if (det == 0.0f) continue;
        const Vec3 s = point - t.p0;
        const float b1 = glm::dot(s, p) / det;
        const Vec3 q = glm::cross(s, t.e1);
        const float b2 = glm::dot(direction, q) / det;
        const float distance = glm::dot(t.e2, q) / det;
        if (b1 < 0.0f || b2 < 0.0f || b1 + b2 > 1.0f || !(distance > 0.0f)) continue;
        const Vec3 cross = glm::cross(t.e1, t.e2);
        const float cross_length = glm::length(cross);
        const float weight = m_cdf[i] - (i == 0 ? 0.0f : m_cdf[i - 1]);
        const float effective_area = 0.5f * cross_length * total / weight;
        density += flat_pdf(point, point + distance * direction, cross / cross_length,
                            effective_area, direction, t.two_sided);
    }
    return density;
}

float MeshEmitter::pdf_at(const Vec3& point, const EmitterPoint& at) const {
    if (m_triangles.empty()) return 0.0f;
    const Vec3 offset = at.position - point;
    const float distance2 = glm::dot(offset, offset);
    const float cos_light = -glm::dot(at.normal, offset) / std::sqrt(distance2);
    if (!(cos_light > 0.0f)) return 0.0f;
    return luminance(at.radiance) / m_cdf.back() * distance2 / cos_light;
}

float AreaLight::pdf_at(const Vec3& point, const Vec3& direction, const EmitterPoint& at) const {
    if (shape == Shape::Mesh) return mesh ? mesh->pdf_at(point, at) : 0.0f;
    return pdf(point, direction);
}

float AreaLight::pdf(const Vec3& point, const Vec3& direction) const {
    switch (shape) {
        case Shape::Mesh:
            return mesh ? mesh->pdf(point, direction) : 0.0f;
        case Shape::Rectangle: {
            const Vec3 n = unit_vector(glm::cross(edge1, edge2));
            Vec3 hit;
            if (!plane_crossing(point, direction, corner, n, hit)) return 0.0f;
            // The point's coordinates (a, b) in the edges' basis (the edges need not be
            // perpendicular): the 2×2 normal equations.
            const Vec3 local = hit - corner;
            const float e11 = glm::dot(edge1, edge1), e22 = glm::dot(edge2, edge2),
                        e12 = glm::dot(edge1, edge2);
            const float d1 = glm::dot(local, edge1), d2 = glm::dot(local, edge2);
            const float det = e11 * e22 - e12 * e12;
            const float a = (d1 * e22 - d2 * e12) / det;
            const float b = (d2 * e11 - d1 * e12) / det;
            if (a < 0.0f || a > 1.0f || b < 0.0f || b > 1.0f) return 0.0f;
            return flat_pdf(point, hit, n, area(), direction);
        }
        case Shape::Disk: {
            Vec3 hit;
            if (!plane_crossing(point, direction, center, normal, hit)) return 0.0f;
            const Vec3 r = hit - center;
            if (glm::dot(r, r) > radius * radius) return 0.0f;
            return flat_pdf(point, hit, normal, area(), direction);
        }
        case Shape::Sphere:
            break;
    }
    // Sphere: uniform over the cone of directions it subtends (sample).
    const Vec3 to_center = center - point;
    const float dc = glm::length(to_center);
    if (!(dc > radius)) return 0.0f;
    const float sin2_max = (radius / dc) * (radius / dc);
    const float one_minus_cos_max = sin2_max / (1.0f + std::sqrt(1.0f - sin2_max));
    const float cos_theta = glm::dot(direction, to_center) / dc;
    if (cos_theta < 1.0f - one_minus_cos_max) return 0.0f;
    return 1.0f / (2.0f * kPi * one_minus_cos_max);
}

}  // namespace rayo
