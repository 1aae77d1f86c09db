#pragma once
// The geometric scene: camera and primitives with material ids. Materials and lights live in
// shading/ (core knows nothing of shading); the loaders fill both.
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/scene_limits.h"
#include "core/shapes/cone.h"
#include "core/shapes/mesh.h"
#include "core/shapes/sphere.h"

namespace rayo {

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
