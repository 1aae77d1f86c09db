#pragma once
// Instancing (issue 11 item 7): a named group of objects stored once, placed any number of times
// by an affine transform. The accel builds one Embree scene per instanced group and one Embree
// instance geometry per placement (core/instance_binding.h), so the group's shapes, meshes and
// BVH are held once however often it appears.
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <limits>
#include <string>
#include <vector>

#include "core/shapes/mesh.h"
#include "core/shapes/registry.h"

namespace rayo {

// Instances of instances would need Embree's multi-level instancing; Debian's Embree 3.13 is
// built with RTC_MAX_INSTANCE_LEVEL_COUNT 1 (core/instance_binding.cpp checks it), so a group
// may not contain instances.
constexpr int kMaxInstanceLevels = 1;

// The objects of one group, in the group's own (object) space.
struct ShapeGroup {
    std::string name;
    Shapes shapes;
    std::vector<TriangleMesh> meshes;

    // Analytic shapes plus triangles: what one instance of the group puts in the scene.
    size_t object_count() const {
        size_t n = 0;
        shapes.for_each([&](const auto& v) { n += v.size(); });
        for (const TriangleMesh& m : meshes) n += m.triangle_count();
        return n;
    }
};

constexpr uint32_t kNoMaterialOverride = std::numeric_limits<uint32_t>::max();

// One placement of a group: world = transform · object (an invertible affine map; the JSON
// reader refuses others), optionally with every object's material replaced.
struct Instance {
    uint32_t group = 0;
    glm::mat4 transform{1.0f};
    uint32_t material = kNoMaterialOverride;
};

}  // namespace rayo
