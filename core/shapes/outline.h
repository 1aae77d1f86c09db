#pragma once
// Outlines for the wireframe preview (docs/preview.md): what each shape looks like drawn as
// lines from one eye point, as 3-D segments. Every shape in the registry (core/shapes/registry.h)
// and the triangle mesh has `void outline(Outline& out) const`; a shape without one does not
// compile in draw_wireframe (core/wireframe.h). Curves (circles) are divided finely enough that
// each chord stays within a quarter pixel of the curve on the image.
#include <vector>

#include "core/math.h"

namespace rayo {

// Where the outline is seen from: the eye, and the angle a pixel subtends (radians), which sets
// how many chords a circle gets.
struct OutlineView {
    DVec3 eye{0.0};
    double pixel_angle = 1e-3;
};

struct OutlineSegment {
    DVec3 a{0.0}, b{0.0};
};

class Outline {
  public:
    explicit Outline(const OutlineView& view) : m_view(view) {}

    const OutlineView& view() const { return m_view; }
    const std::vector<OutlineSegment>& segments() const { return m_segments; }
    void clear() { m_segments.clear(); }

    void add_segment(const DVec3& a, const DVec3& b) { m_segments.push_back({a, b}); }
    // The circle of `radius` about `center` in the plane with unit normal `normal`, as a closed
    // polyline of chords whose sagitta, seen from the eye, is at most kMaxSagittaPixels.
    void add_circle(const DVec3& center, const DVec3& normal, double radius);
    // How many chords add_circle uses for a circle of `radius` whose nearest point is at least
    // `distance` from the eye.
    int circle_chords(double radius, double distance) const;

    static constexpr double kMaxSagittaPixels = 0.25;
    static constexpr int kMinChords = 8;
    static constexpr int kMaxChords = 4096;

  private:
    OutlineView m_view;
    std::vector<OutlineSegment> m_segments;
};

// Two unit vectors that make (u, v, n) an orthonormal frame around the unit vector n.
void perpendicular_frame(const DVec3& n, DVec3& u, DVec3& v);

}  // namespace rayo
