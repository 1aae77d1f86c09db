// The shadow terminator of smooth-shaded triangles (core/shadow_terminator.h; Hanika, Ray Tracing
// Gems II ch. 4): the offset itself against the sphere a coarse icosphere approximates, and the
// lit region of that icosphere against the exact sphere's, with and without the offset.
#include "core/shadow_terminator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "apps/scene/json_loader.h"
#include "core/accel.h"
#include "core/shapes/icosphere.h"
#include "shading/integrators/whitted.h"

namespace rayo {
namespace {

TEST(ShadowTerminatorOffset, FlatTriangleWithItsFaceNormalHasNone) {
    const Vec3 corners[3] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    const Vec3 normals[3] = {Vec3(0, 0, 2), Vec3(0, 0, 1), Vec3(0, 0, 1)};
    const float weights[3] = {0.2f, 0.3f, 0.5f};
    const Vec3 p = 0.2f * corners[0] + 0.3f * corners[1] + 0.5f * corners[2];
    EXPECT_EQ(terminator_offset(p, corners, normals, weights), Vec3(0.0f));
}

TEST(ShadowTerminatorOffset, LiftsAFacetPointTowardTheSphereItsNormalsDescribe) {
    // Every face of a level-0 icosphere (corners on the unit sphere, radial normals): points
    // inside the face lie below the sphere; the offset moves them outward, closer to it, and
    // never above it (each corner's tangent plane lies outside the sphere's interior).
    const Icosphere unit = make_icosphere(0);
    for (const auto& tri : unit.triangles) {
        const Vec3 corners[3] = {unit.positions[tri[0]], unit.positions[tri[1]],
                                 unit.positions[tri[2]]};
        const float weights[3] = {0.2f, 0.3f, 0.5f};
        const Vec3 p = weights[0] * corners[0] + weights[1] * corners[1] + weights[2] * corners[2];
        const Vec3 lifted = p + terminator_offset(p, corners, corners, weights);
        EXPECT_LT(glm::length(p), 0.9f);
        EXPECT_GT(glm::length(lifted), glm::length(p) + 0.05f);
        // Above the sphere by no more than the corners' tangent planes allow (sec θ − 1, with
        // θ ≈ 63° the icosahedron's corner-to-corner angle: < 1.3).
        EXPECT_LT(glm::length(lifted), 1.3f);
        // Outward along the face normal, not sideways off the face.
        const Vec3 face =
            glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
        EXPECT_GT(glm::dot(lifted - p, face), 0.9f * glm::length(lifted - p));
    }
}

// A unit sphere lit by a directional light from the side, seen from +z, traced either exactly
// or as a level-1 icosphere (80 smooth-shaded triangles).
struct LitSphere {
    LitSphere(SphereMethod method, bool offset)
        : description(load_json_string(kScene, "scene.json", "")),
          accel(description.scene, options(method)),
          integrator(accel, description.shading, settings(offset)) {}
    static constexpr const char* kScene = R"({"rayo": 1, "background": [0, 0, 0],
      "ambient_light": 0,
      "materials": {"default": {"ka": 0, "kd": 1, "ks": 0}},
      "lights": [{"type": "directional", "direction": [-1, -0.3, -0.2], "intensity": 1}],
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})";
    static AccelOptions options(SphereMethod method) {
        AccelOptions o;
        o.spheres = SphereRepresentation{method, 1, true};
        return o;
    }
    WhittedSettings settings(bool offset) const {
        WhittedSettings s = description.settings.whitted();
        s.terminator_offset = offset;
        return s;
    }
    Vec3 radiance(float x, float y) {
        Ray ray;
        ray.origin = Vec3(x, y, 5.0f);
        ray.direction = Vec3(0.0f, 0.0f, -1.0f);
        return integrator.radiance(ray, counters);
    }
    SceneDescription description;
    Accel accel;
    WhittedIntegrator integrator;
    RayCounters counters;
};

// Over a 41×41 grid of rays across the sphere: how many points the exact sphere shows lit
// (n·l > 0.02 of the light) come out black on the icosphere.
int lit_points_shown_dark(bool offset) {
    LitSphere exact(SphereMethod::User, true), mesh(SphereMethod::Mesh, offset);
    int dark = 0;
    for (int j = 0; j <= 40; ++j) {
        for (int i = 0; i <= 40; ++i) {
            const float x = -1.0f + i / 20.0f, y = -1.0f + j / 20.0f;
            if (x * x + y * y > 0.8f) continue;  // off the icosphere's silhouette
            if (exact.radiance(x, y).x > 0.02f && mesh.radiance(x, y).x == 0.0f) ++dark;
        }
    }
    return dark;
}

TEST(ShadowTerminator, CoarseSmoothSphereIsLitWhereTheExactSphereIs) {
    // Without the offset, facets turned from the light by their flat normal are black although
    // their interpolated normals face it: the stair-step terminator. With it, none are.
    EXPECT_GT(lit_points_shown_dark(false), 20);
    EXPECT_EQ(lit_points_shown_dark(true), 0);
}

}  // namespace
}  // namespace rayo
