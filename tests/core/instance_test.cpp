// Tests of instancing (core/instance.h, core/instance_binding.h): an identity instance hits
// exactly where the group's objects placed directly do; a moved, scaled or rotated instance of
// a sphere hits at the closed-form point with the closed-form normal (for a non-uniform scale,
// the inverse transpose); shadows and coherent batches go through instances; instances share
// one group scene.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "core/accel.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec_near;

AccelOptions user_spheres() {
    AccelOptions options;
    options.spheres.method = SphereMethod::User;
    return options;
}

// Two spheres and a quad, the objects both placed directly and grouped.
template <typename Objects>
void add_objects(Objects& objects) {
    objects.shapes.template of<Sphere>().push_back({Vec3(0.0f, 0.0f, 0.0f), 1.0f, 1});
    objects.shapes.template of<Sphere>().push_back({Vec3(2.5f, 0.5f, -1.0f), 0.7f, 2});
    TriangleMesh quad;
    quad.add_convex_polygon({Vec3(-3, -3, -2), Vec3(3, -3, -2), Vec3(3, 3, -2), Vec3(-3, 3, -2)},
                            {}, 3);
    objects.meshes.push_back(quad);
}

Scene one_instance(const glm::mat4& transform, uint32_t material = kNoMaterialOverride) {
    Scene scene;
    ShapeGroup group;
    group.name = "g";
    add_objects(group);
    scene.groups.push_back(group);
    scene.instances.push_back({0, transform, material});
    return scene;
}

// Rays from above the scene, on a grid, toward a point below it.
std::vector<Ray> grid_rays() {
    std::vector<Ray> rays;
    for (int y = -20; y <= 20; ++y) {
        for (int x = -20; x <= 20; ++x) {
            Ray r;
            r.origin = Vec3(0.3f, -0.2f, 6.0f);
            r.direction = glm::normalize(Vec3(0.17f * x, 0.17f * y, -6.0f));
            rays.push_back(r);
        }
    }
    return rays;
}

TEST(Instance, IdentityInstanceHitsWhereTheObjectsPlacedDirectlyDo) {
    Scene direct;
    add_objects(direct);
    const Accel a(direct, user_spheres());
    const Scene instanced = one_instance(glm::mat4(1.0f));  // outlives the accel (it refers to it)
    const Accel b(instanced, user_spheres());
    int hits = 0;
    for (const Ray& ray : grid_rays()) {
        SurfaceHit ha, hb;
        const bool fa = a.intersect(ray, ha);
        ASSERT_EQ(fa, b.intersect(ray, hb));
        if (!fa) continue;
        ++hits;
        // t, the position and the material: the same bits (the identity maps them exactly).
        EXPECT_EQ(ha.t, hb.t);
        EXPECT_EQ(ha.position, hb.position);
        EXPECT_EQ(ha.material, hb.material);
        EXPECT_EQ(ha.shape, hb.shape);
        EXPECT_EQ(ha.primitive, hb.primitive);
        EXPECT_EQ(ha.object_size, hb.object_size);
        EXPECT_EQ(ha.instance, kNoInstance);
        EXPECT_EQ(hb.instance, 0u);
        // The normals are renormalised after the (identity) inverse transpose: float rounding.
        expect_vec_near(hb.geometric_normal, ha.geometric_normal, 2e-7);
        expect_vec_near(hb.shading_normal, ha.shading_normal, 2e-7);
    }
    EXPECT_GT(hits, 500);
}

// A unit sphere at the origin in a group, placed by `m`; the ray's closed-form hit on the image,
// the ellipsoid {p : |S⁻¹R⁻¹(p − c)| = 1}, in double.
struct Placed {
    glm::dvec3 scale, translate;
    double angle_z;  // degrees
    glm::mat4 matrix() const {
        glm::dmat4 m = glm::translate(glm::dmat4(1.0), translate);
        m = glm::rotate(m, glm::radians(angle_z), glm::dvec3(0, 0, 1));
        return glm::mat4(glm::scale(m, scale));
    }
};

void expect_closed_form_hit(const Placed& placed, const Ray& ray) {
    Scene scene;
    ShapeGroup group;
    group.shapes.of<Sphere>().push_back({Vec3(0.0f), 1.0f, 0});
    scene.groups.push_back(group);
    scene.instances.push_back({0, placed.matrix()});
    const Accel accel(scene, user_spheres());

    // Object space: o' = M⁻¹o, d' = M⁻¹d (linear part); |o' + t d'|² = 1.
    const glm::dmat4 m = glm::dmat4(placed.matrix());
    const glm::dmat4 inv = glm::inverse(m);
    const glm::dvec3 o(inv * glm::dvec4(glm::dvec3(ray.origin), 1.0));
    const glm::dvec3 d(inv * glm::dvec4(glm::dvec3(ray.direction), 0.0));
    const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - 1.0;
    const double t = (-b - std::sqrt(b * b - a * c)) / a;
    const glm::dvec3 p_object = o + t * d;
    const glm::dvec3 p = glm::dvec3(m * glm::dvec4(p_object, 1.0));
    // The implicit F(p) = |M⁻¹p|² − 1 has gradient 2·M⁻ᵀ·M⁻¹p: the inverse transpose.
    const glm::dvec3 n = glm::normalize(glm::transpose(glm::dmat3(inv)) * p_object);

    SurfaceHit hit;
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_NEAR(hit.t, t, 2e-5 * t);
    expect_vec_near(glm::dvec3(hit.position), p, 2e-5);
    expect_vec_near(glm::dvec3(hit.geometric_normal), n, 2e-5);
    expect_vec_near(glm::dvec3(hit.shading_normal), n, 2e-5);
    EXPECT_NEAR(glm::length(hit.geometric_normal), 1.0f, 1e-6f);
    // The shadow ray through the instance: blocked before the hit, clear just short of it.
    Ray shadow = ray;
    EXPECT_TRUE(accel.occluded(shadow));
    shadow.tfar = static_cast<float>(0.99 * t);
    EXPECT_FALSE(accel.occluded(shadow));
}

Ray ray_from(const Vec3& origin, const Vec3& target) {
    Ray r;
    r.origin = origin;
    r.direction = glm::normalize(target - origin);
    return r;
}

TEST(Instance, TranslatedSphereHitsAtTheClosedFormPoint) {
    const Placed placed{glm::dvec3(1.0), glm::dvec3(3, -2, 5), 0.0};
    expect_closed_form_hit(placed, ray_from(Vec3(0, 0, 20), Vec3(3.3f, -1.8f, 5.0f)));
}

TEST(Instance, UniformlyScaledRotatedSphereHitsAtTheClosedFormPoint) {
    const Placed placed{glm::dvec3(2.5), glm::dvec3(-1, 4, 0.5), 37.0};
    expect_closed_form_hit(placed, ray_from(Vec3(10, -3, 8), Vec3(-0.2f, 4.9f, 1.0f)));
}

TEST(Instance, NonUniformScaleNormalIsTheInverseTranspose) {
    // An ellipsoid of semi-axes (1, 3, 0.5) turned by 30°: the mapped normal M·n would be off
    // the surface's normal by tens of degrees here.
    const Placed placed{glm::dvec3(1.0, 3.0, 0.5), glm::dvec3(0, 0, 1), 30.0};
    expect_closed_form_hit(placed, ray_from(Vec3(6, 5, 4), Vec3(0.4f, 1.5f, 1.2f)));
    expect_closed_form_hit(placed, ray_from(Vec3(-7, 1, -3), Vec3(-0.3f, -1.0f, 0.8f)));
}

TEST(Instance, MirroringInstanceKeepsNormalsOutward) {
    const Placed placed{glm::dvec3(-1.0, 2.0, 1.0), glm::dvec3(0.0), 0.0};
    expect_closed_form_hit(placed, ray_from(Vec3(5, 4, 3), Vec3(0.2f, 0.6f, 0.1f)));
}

TEST(Instance, CoherentBatchesEqualSingleRaysThroughInstances) {
    const Scene scene =
        one_instance(Placed{glm::dvec3(0.8, 1.2, 1.0), glm::dvec3(0.5, 0, 0), 20}.matrix());
    const Accel accel(scene, user_spheres());
    const std::vector<Ray> rays = grid_rays();
    std::vector<SurfaceHit> hits(rays.size());
    std::unique_ptr<bool[]> found(new bool[rays.size()]), occluded(new bool[rays.size()]);
    accel.intersect_coherent(rays.data(), static_cast<int>(rays.size()), hits.data(), found.get());
    accel.occluded_coherent(rays.data(), static_cast<int>(rays.size()), occluded.get());
    for (size_t i = 0; i < rays.size(); ++i) {
        SurfaceHit single;
        ASSERT_EQ(found[i], accel.intersect(rays[i], single));
        EXPECT_EQ(occluded[i], found[i]);
        if (!found[i]) continue;
        EXPECT_NEAR(hits[i].t, single.t, 1e-5f * single.t);
        EXPECT_EQ(hits[i].material, single.material);
    }
}

TEST(Instance, MaterialOverrideReplacesTheGroupsMaterials) {
    const Scene a_scene = one_instance(glm::mat4(1.0f)), b_scene = one_instance(glm::mat4(1.0f), 7);
    const Accel plain(a_scene, user_spheres());
    const Accel overridden(b_scene, user_spheres());
    std::vector<uint32_t> seen;
    for (const Ray& ray : grid_rays()) {
        SurfaceHit a, b;
        if (!plain.intersect(ray, a)) continue;
        ASSERT_TRUE(overridden.intersect(ray, b));
        seen.push_back(a.material);
        EXPECT_EQ(b.material, 7u);
    }
    EXPECT_NE(std::find(seen.begin(), seen.end(), 1u), seen.end());  // group's own: 1, 2, 3
    EXPECT_NE(std::find(seen.begin(), seen.end(), 3u), seen.end());
}

TEST(Instance, ParameterizationIsTheObjectSpaceOneWithTheTangentMapped) {
    const glm::mat4 m = Placed{glm::dvec3(2.0), glm::dvec3(1, 1, 1), 90.0}.matrix();
    const Scene scene = one_instance(m);
    const Accel accel(scene, user_spheres());
    Ray ray = ray_from(Vec3(1.2f, 1.1f, 9.0f), Vec3(1.0f, 1.0f, 1.0f));
    SurfaceHit hit;
    ASSERT_TRUE(accel.intersect(ray, hit));
    ASSERT_EQ(hit.shape, (Shapes::index_of<Sphere>()));
    accel.parameterize(hit);
    SurfaceHit expected;
    const Sphere unit{Vec3(0.0f), 1.0f, 1};
    unit.parameterization(Vec3(glm::inverse(m) * glm::vec4(hit.position, 1.0f)), expected);
    EXPECT_NEAR(hit.uv.x, expected.uv.x, 1e-5f);
    EXPECT_NEAR(hit.uv.y, expected.uv.y, 1e-5f);
    expect_vec_near(hit.dpdu, glm::mat3(m) * expected.dpdu, 1e-4);
}

TEST(Instance, InstancesShareOneGroupScene) {
    // A group of 2000 spheres: one instance against 200. The instanced primitive count grows
    // with the instances; what is stored, and Embree's memory beyond the instance records, not.
    auto scene_with = [](int count) {
        Scene scene;
        ShapeGroup group;
        for (int i = 0; i < 2000; ++i) {
            group.shapes.of<Sphere>().push_back({Vec3(0.01f * i, std::sin(0.1f * i), 0), 0.02f, 0});
        }
        scene.groups.push_back(group);
        for (int i = 0; i < count; ++i) {
            scene.instances.push_back(
                {0, glm::translate(glm::mat4(1.0f), Vec3(0.0f, 0.0f, 3.0f * i))});
        }
        return scene;
    };
    const Scene one_scene = scene_with(1), many_scene = scene_with(200);
    const Accel one(one_scene, user_spheres());
    const Accel many(many_scene, user_spheres());
    EXPECT_EQ(one.primitive_count(), 2000u);
    EXPECT_EQ(many.primitive_count(), 200u * 2000u);
    EXPECT_EQ(one.stored_primitive_count(), 2000u);
    EXPECT_EQ(many.stored_primitive_count(), 2000u);
    EXPECT_EQ(many.instance_count(), 200u);
    // 199 more instances: their geometries and the top BVH's nodes, well under 1 KB each,
    // against the group's BVH (tens of bytes per sphere) that a copy per instance would repeat.
    ASSERT_GT(one.embree_bytes(), 0u);
    EXPECT_LT(many.embree_bytes(), one.embree_bytes() + 199u * 1024u);
    EXPECT_LT(many.embree_bytes(), 2 * one.embree_bytes());
}

}  // namespace
}  // namespace rayo
