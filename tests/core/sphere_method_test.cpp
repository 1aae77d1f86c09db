// The selectable sphere methods (bruteforce, user, embree-point, mesh:N) and precisions
// (seed, stable, double) against each other and the icosphere tessellation.
#include "core/sphere_method.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "core/accel.h"
#include "core/shapes/icosphere.h"

namespace rayo {
namespace {

TEST(SphereMethodNames, ParseAndPrintRoundTrip) {
    for (const char* name : {"bruteforce", "user", "embree-point", "auto", "mesh:0", "mesh:7"}) {
        const auto parsed = parse_sphere_method(name);
        ASSERT_TRUE(parsed) << name;
        EXPECT_EQ(sphere_method_name(*parsed), name);
    }
    EXPECT_EQ(parse_sphere_method("mesh:3")->mesh_level, 3);
    for (const char* bad : {"", "mesh", "mesh:", "mesh:8", "mesh:-1", "mesh:2x", "User", "bvh"}) {
        EXPECT_FALSE(parse_sphere_method(bad)) << bad;
    }
    EXPECT_EQ(parse_sphere_math("double"), SphereMath::Double);
    EXPECT_EQ(parse_sphere_math("seed"), SphereMath::Seed);
    EXPECT_FALSE(parse_sphere_math("fast"));
    EXPECT_STREQ(sphere_math_name(SphereMath::Stable), "stable");
}

TEST(Icosphere, MaxDepthTableMatchesTheTessellation) {
    for (int level = 0; level <= 5; ++level) {
        const Icosphere s = make_icosphere(level);
        double deepest = 0.0;
        for (const auto& t : s.triangles) {
            const glm::dvec3 a(s.positions[t[0]]), b(s.positions[t[1]]), c(s.positions[t[2]]);
            const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
            deepest = std::max(deepest, 1.0 - glm::dot(n, a));
        }
        EXPECT_NEAR(deepest, kIcosphereMaxDepth[level], 1e-6 * kIcosphereMaxDepth[level] + 1e-9)
            << level;
    }
}

TEST(Icosphere, CountsUnitVerticesAndOutwardWinding) {
    for (int level = 0; level <= 4; ++level) {
        const Icosphere s = make_icosphere(level);
        EXPECT_EQ(static_cast<long long>(s.triangles.size()), icosphere_triangles(level));
        EXPECT_EQ(s.positions.size(), static_cast<size_t>(10 * (1 << (2 * level)) + 2));
        for (const Vec3& p : s.positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-6f);
        for (const auto& t : s.triangles) {
            const Vec3 n = glm::cross(s.positions[t[1]] - s.positions[t[0]],
                                      s.positions[t[2]] - s.positions[t[0]]);
            const Vec3 centroid = (s.positions[t[0]] + s.positions[t[1]] + s.positions[t[2]]);
            ASSERT_GT(glm::dot(n, centroid), 0.0f) << "level " << level;
        }
    }
}

Scene random_spheres(int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> position(-10.0f, 10.0f), radius(0.2f, 1.5f);
    Scene scene;
    for (int i = 0; i < count; ++i) {
        scene.shapes.of<Sphere>().push_back({Vec3(position(rng), position(rng), position(rng)),
                                             radius(rng), static_cast<uint32_t>(i)});
    }
    return scene;
}

std::vector<Ray> random_rays(int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> position(-15.0f, 15.0f), target(-8.0f, 8.0f);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        Ray ray;
        ray.origin = Vec3(position(rng), position(rng), 30.0f);
        ray.direction = glm::normalize(Vec3(target(rng), target(rng), 0.0f) - ray.origin);
        rays.push_back(ray);
    }
    return rays;
}

AccelOptions options_for(const char* method, SphereMath math = SphereMath::Stable) {
    AccelOptions o;
    o.spheres = *parse_sphere_method(method);
    o.sphere_math = math;
    return o;
}

TEST(SphereMethods, BruteForceAndUserGeometryAgreeExactly) {
    const Scene scene = random_spheres(200, 7);
    const Accel user(scene, options_for("user")), brute(scene, options_for("bruteforce"));
    EXPECT_EQ(brute.primitive_count(), 200u);
    int hits = 0;
    for (const Ray& ray : random_rays(20000, 8)) {
        SurfaceHit a, b;
        const bool ha = user.intersect(ray, a), hb = brute.intersect(ray, b);
        ASSERT_EQ(ha, hb);
        ASSERT_EQ(user.occluded(ray), brute.occluded(ray));
        if (!ha) continue;
        ++hits;
        EXPECT_EQ(a.t, b.t);  // same quadratic, same inputs: the same float
        EXPECT_EQ(a.material, b.material);
    }
    EXPECT_GT(hits, 2000);
}

TEST(SphereMethods, EmbreePointAgreesWithAnalyticAwayFromSilhouettes) {
    const Scene scene = random_spheres(200, 9);
    const Accel user(scene, options_for("user")), point(scene, options_for("embree-point"));
    int disagreements = 0, hits = 0;
    for (const Ray& ray : random_rays(20000, 10)) {
        SurfaceHit a, b;
        const bool ha = user.intersect(ray, a), hb = point.intersect(ray, b);
        if (ha != hb || (ha && a.material != b.material)) {
            ++disagreements;
            continue;
        }
        if (!ha) continue;
        ++hits;
        EXPECT_NEAR(a.t, b.t, 1e-4f * a.t);
    }
    EXPECT_GT(hits, 2000);
    EXPECT_LE(disagreements, 5);  // only rays grazing a silhouette within float precision
}

TEST(SphereMethods, MeshConvergesToTheSphereWithLevel) {
    const Scene scene = random_spheres(50, 11);
    const Accel user(scene, options_for("user"));
    const std::vector<Ray> rays = random_rays(20000, 12);
    double previous_error = 1e30;
    for (int level : {0, 2, 4}) {
        const std::string name = "mesh:" + std::to_string(level);
        const Accel mesh(scene, options_for(name.c_str()));
        EXPECT_EQ(mesh.primitive_count(), 50u * icosphere_triangles(level));
        double max_error = 0.0;
        int mismatches = 0;
        for (const Ray& ray : rays) {
            SurfaceHit a, b;
            const bool ha = user.intersect(ray, a), hb = mesh.intersect(ray, b);
            if (ha != hb || (ha && a.material != b.material)) {
                ++mismatches;
                continue;
            }
            // Radial depth of the mesh hit below the true surface, in radii: the inscribed
            // icosphere lies inside the sphere by at most the facet sagitta.
            if (ha) {
                const Sphere& s = scene.shapes.of<Sphere>()[a.material];
                max_error = std::max(max_error,
                                     1.0 - double(glm::length(b.position - s.center)) / s.radius);
            }
        }
        EXPECT_LE(max_error, kIcosphereMaxDepth[level] + 1e-5) << name;
        EXPECT_GT(max_error, 0.5 * kIcosphereMaxDepth[level]) << name;  // the bound is tight
        EXPECT_LT(max_error, previous_error) << name;
        previous_error = max_error;
        EXPECT_LT(mismatches, 2000) << name;
    }
}

TEST(SphereMethods, DoubleMathMatchesStableOnOrdinaryScenes) {
    const Scene scene = random_spheres(100, 13);
    const Accel stable(scene, options_for("user")),
        twice(scene, options_for("user", SphereMath::Double));
    for (const Ray& ray : random_rays(5000, 14)) {
        SurfaceHit a, b;
        const bool ha = stable.intersect(ray, a), hb = twice.intersect(ray, b);
        ASSERT_EQ(ha, hb);
        if (ha) {
            EXPECT_NEAR(a.t, b.t, 2e-6f * a.t);
        }
    }
}

// Ray streams (intersect_coherent/occluded_coherent) equal the single-ray calls ray by ray for
// the methods whose kernels are ours or Embree's triangles, in Embree's coherent and incoherent
// stream modes (the random rays scatter like secondary rays); batches longer than one call.
TEST(SphereMethods, CoherentBatchesMatchSingleRays) {
    Scene scene = random_spheres(100, 21);
    TriangleMesh floor;
    floor.add_convex_polygon(
        {Vec3(-20, -20, -12), Vec3(20, -20, -12), Vec3(20, 20, -12), Vec3(-20, 20, -12)}, {}, 0);
    scene.meshes.push_back(floor);
    const std::vector<Ray> rays = random_rays(1000, 22);
    for (const char* method : {"user", "bruteforce", "mesh:1"}) {
        for (const Accel::Coherence coherence :
             {Accel::Coherence::Coherent, Accel::Coherence::Incoherent}) {
            const Accel accel(scene, options_for(method));
            std::vector<SurfaceHit> hits(rays.size());
            std::unique_ptr<bool[]> found(new bool[rays.size()]), blocked(new bool[rays.size()]);
            accel.intersect_coherent(rays.data(), static_cast<int>(rays.size()), hits.data(),
                                     found.get(), coherence);
            accel.occluded_coherent(rays.data(), static_cast<int>(rays.size()), blocked.get(),
                                    coherence);
            int hit_count = 0;
            for (size_t i = 0; i < rays.size(); ++i) {
                SurfaceHit single;
                ASSERT_EQ(found[i], accel.intersect(rays[i], single)) << method << " ray " << i;
                ASSERT_EQ(blocked[i], accel.occluded(rays[i])) << method << " ray " << i;
                if (!found[i]) continue;
                ++hit_count;
                EXPECT_EQ(hits[i].t, single.t);
                EXPECT_EQ(hits[i].position, single.position);
                EXPECT_EQ(hits[i].shading_normal, single.shading_normal);
                EXPECT_EQ(hits[i].material, single.material);
            }
            EXPECT_GT(hit_count, 500) << method;
        }
    }
}

TEST(SphereMethods, AccelRefusesAnUnresolvedAuto) {
    const Scene scene = random_spheres(3, 1);
    EXPECT_THROW(Accel(scene, options_for("auto")), std::logic_error);
}

TEST(SphereMethods, SphereBelowOneUlpOfItsPositionGivesFiniteHits) {
    // Radius 1e-3 at x = 1e5, where floats are 0.0078 apart: a ray along x hits it, and the hit
    // point o + t·d rounds onto the centre. The hit must still be finite (it faces the ray).
    Scene scene;
    scene.shapes.of<Sphere>().push_back({Vec3(1e5f, 0.0f, 0.0f), 1e-3f, 0});
    const Accel accel(scene, options_for("user"));
    Ray ray;
    ray.origin = Vec3(1e5f + 16.0f, 0.0f, 0.0f);
    ray.direction = Vec3(-1.0f, 0.0f, 0.0f);
    SurfaceHit hit;
    ASSERT_TRUE(accel.intersect(ray, hit));
    ASSERT_EQ(ray.at(hit.t), scene.shapes.of<Sphere>()[0].center);  // the degenerate case, really
    for (int a = 0; a < 3; ++a) {
        EXPECT_TRUE(std::isfinite(hit.position[a]));
        EXPECT_TRUE(std::isfinite(hit.geometric_normal[a]));
    }
    EXPECT_EQ(hit.geometric_normal, -ray.direction);
}

}  // namespace
}  // namespace rayo