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

float largest_triangle_coordinate(const Scene& scene, bool spheres_as_triangles) {
    float largest = 0.0f;
    for (const TriangleMesh& m : scene.meshes) {
        for (const Vec3& p : m.positions) largest = glm::max(largest, max_abs_component(p));
    }
    if (spheres_as_triangles) {
        for (const Sphere& s : scene.shapes.of<Sphere>()) {
            const Bounds3 b = s.bounds();
            largest =
                glm::max(largest, glm::max(max_abs_component(b.lower), max_abs_component(b.upper)));
        }
    }
    for (const Instance& instance : scene.instances) {
        for (const TriangleMesh& mesh : scene.groups[instance.group].meshes) {
            for (const Vec3& p : mesh.positions) {
                largest = glm::max(
                    largest, max_abs_component(Vec3(instance.transform * glm::vec4(p, 1.0f))));
            }
        }
    }
    return largest;
}

size_t objects_below_float_resolution(const Scene& scene) {
    size_t count = 0;
    auto check = [&](const Bounds3& b) {
        const Vec3 side = b.upper - b.lower;
        const float size = glm::max(side.x, glm::max(side.y, side.z));
        const float distance = glm::max(max_abs_component(b.lower), max_abs_component(b.upper));
        if (size < kMinSizeToDistance * distance) ++count;
    };
    scene.shapes.for_each([&](const auto& shapes) {
        for (const auto& s : shapes) check(s.bounds());
    });
    for (const TriangleMesh& m : scene.meshes) {
        if (m.positions.empty()) continue;
        Bounds3 b{m.positions.front(), m.positions.front()};
        for (const Vec3& p : m.positions) b = {glm::min(b.lower, p), glm::max(b.upper, p)};
        check(b);
    }
    for (const HeightField& h : scene.heightfields) check(h.bounds());
    for (const VoxelGrid& v : scene.voxels) check(v.bounds());
    return count;
}

}  // namespace rayo
