#pragma once
// The geometric scene: camera and primitives with material ids. Materials and lights live in
// shading/ (core knows nothing of shading); the loaders fill both.
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/cone.h"
#include "core/mesh.h"
#include "core/sphere.h"

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
