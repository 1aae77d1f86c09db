#pragma once
// The geometric scene: camera and primitives with material ids. Materials and lights live in
// shading/ (core knows nothing of shading); the loaders fill both.
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/shapes/cone.h"
#include "core/shapes/mesh.h"
#include "core/shapes/sphere.h"

namespace rayo {

// The largest magnitude a scene number may have. Intersections square coordinates and radii
// (r², |f|², the discriminant), and 1e18² = 1e36 stays finite in float while 1e20² does not: a
// larger sphere would silently vanish. The loaders refuse anything beyond it (docs/limits.md).
constexpr double kMaxSceneMagnitude = 1e18;

struct Scene {
    CameraDesc camera;
    std::vector<Sphere> spheres;
    std::vector<Cone> cones;
    std::vector<TriangleMesh> meshes;

    size_t triangle_count() const {
        size_t n = 0;
        for (const auto& m : meshes) n += m.triangle_count();
        return n;
    }
};

}  // namespace rayo
