#include "core/scene_bounds.h"

namespace rayo {

std::optional<Bounds3> scene_bounds(const Scene& scene) {
    std::optional<Bounds3> box;
    auto extend = [&](const Bounds3& b) {
        box = box ? Bounds3{glm::min(box->lower, b.lower), glm::max(box->upper, b.upper)} : b;
    };
    auto extend_point = [&](const Vec3& p) { extend({p, p}); };
    scene.shapes.for_each([&](const auto& shapes) {
        for (const auto& s : shapes) extend(s.bounds());
    });
    for (const TriangleMesh& m : scene.meshes) {
        for (const Vec3& p : m.positions) extend_point(p);
    }
    for (const HeightField& h : scene.heightfields) extend(h.bounds());
    for (const VoxelGrid& v : scene.voxels) extend(v.bounds());
    for (const Instance& instance : scene.instances) {
        const ShapeGroup& group = scene.groups[instance.group];
        const glm::mat4& m = instance.transform;
        for (const TriangleMesh& mesh : group.meshes) {
            for (const Vec3& p : mesh.positions) extend_point(Vec3(m * glm::vec4(p, 1.0f)));
        }
        group.shapes.for_each([&](const auto& shapes) {
            for (const auto& s : shapes) {
                const Bounds3 b = s.bounds();
                for (int corner = 0; corner < 8; ++corner) {
                    const Vec3 p((corner & 1) ? b.upper.x : b.lower.x,
                                 (corner & 2) ? b.upper.y : b.lower.y,
                                 (corner & 4) ? b.upper.z : b.lower.z);
                    extend_point(Vec3(m * glm::vec4(p, 1.0f)));
                }
            }
        });
    }
    return box;
}

}  // namespace rayo
