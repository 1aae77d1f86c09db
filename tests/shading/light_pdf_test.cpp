// The lights' densities for sampling integrators (shading/light.h light_pdf): for every light
// with an extent, pdf(point, direction) is the solid-angle density with which sample() gives the
// direction (the same number sample() reports, for its own directions) and integrates to 1 over
// the sphere of directions; the point, spot and directional lights are deltas with no density.
// The registry tests run over every registered light kind (the Light variant, shading/light.h),
// so a new kind is covered by adding it there.
#include <gtest/gtest.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "shading/light.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec_near;

// ∫ pdf dω over the sphere, on a stratified (cos θ, φ) grid.
double integral_over_sphere(const Light& light, const Vec3& point) {
    constexpr int kRows = 512, kColumns = 1024;
    double sum = 0.0;
    for (int i = 0; i < kRows; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / kRows;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        for (int j = 0; j < kColumns; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / kColumns;
            const Vec3 w(static_cast<float>(r * std::cos(phi)),
                         static_cast<float>(r * std::sin(phi)), static_cast<float>(z));
            sum += light_pdf(light, point, w);
        }
    }
    return sum * 4.0 * kPi / (kRows * kColumns);
}

void expect_consistent(const Light& light, const Vec3& point, const char* what) {
    int sampled = 0;
    for (int i = 0; i < 32; ++i) {
        for (int j = 0; j < 32; ++j) {
            LightSample s;
            if (!sample_light(light, point, glm::vec2((i + 0.37f) / 32, (j + 0.61f) / 32), s)) {
                continue;
            }
            ++sampled;
            EXPECT_NEAR(light_pdf(light, point, s.direction), s.pdf, 2e-3f * s.pdf) << what;
        }
    }
    EXPECT_GT(sampled, 900) << what;
    EXPECT_NEAR(integral_over_sphere(light, point), 1.0, 0.01) << what;
    EXPECT_FALSE(light_is_delta(light));
}

TEST(LightPdf, RectangleDiskSphereAndMeshMatchTheirSamplesAndIntegrateToOne) {
    AreaLight rectangle;
    rectangle.shape = AreaLight::Shape::Rectangle;
    rectangle.corner = Vec3(-1, 2, -1);
    rectangle.edge1 = Vec3(2, 0, 0);
    rectangle.edge2 = Vec3(0.5f, 0, 1.5f);  // not perpendicular to edge1; emits toward −y
    expect_consistent(rectangle, Vec3(0.2f, 0, 0.1f), "rectangle");

    AreaLight disk;
    disk.shape = AreaLight::Shape::Disk;
    disk.center = Vec3(0, 1.5f, 0.5f);
    disk.normal = glm::normalize(Vec3(0.2f, -1, 0));
    disk.radius = 1.2f;
    expect_consistent(disk, Vec3(0, 0, 0), "disk");

    AreaLight sphere;
    sphere.shape = AreaLight::Shape::Sphere;
    sphere.center = Vec3(1, 2, 0);
    sphere.radius = 0.8f;
    expect_consistent(sphere, Vec3(0, 0, 0), "sphere");

    auto emitter = std::make_shared<MeshEmitter>();
    // Two triangles of one quad facing −y, of different radiance (the pick weighs by power).
    emitter->add(Vec3(-1, 2, -1), Vec3(1, 2, -1), Vec3(1, 2, 1), Vec3(1.0f));
    emitter->add(Vec3(-1, 2, -1), Vec3(1, 2, 1), Vec3(-1, 2, 1), Vec3(3.0f));
    AreaLight mesh;
    mesh.shape = AreaLight::Shape::Mesh;
    mesh.mesh = emitter;
    expect_consistent(mesh, Vec3(0.3f, 0, -0.2f), "mesh");
}

TEST(LightPdf, TwoSidedMeshTrianglesAreSampledFromBothSides) {
    // A triangle of a two-sided material (shading/material.h) emits on both sides: a point
    // behind it gets samples whose density its pdf matches; a one-sided triangle gives none.
    auto two_sided = std::make_shared<MeshEmitter>();
    two_sided->add(Vec3(-1, 2, -1), Vec3(1, 2, -1), Vec3(1, 2, 1), Vec3(1.0f), true);
    two_sided->add(Vec3(-1, 2, -1), Vec3(1, 2, 1), Vec3(-1, 2, 1), Vec3(3.0f), true);
    AreaLight mesh;
    mesh.shape = AreaLight::Shape::Mesh;
    mesh.mesh = two_sided;
    const Vec3 behind(0.3f, 4.0f, -0.2f), in_front(0.3f, 0.0f, -0.2f);
    expect_consistent(mesh, behind, "two-sided mesh, behind");
    expect_consistent(mesh, in_front, "two-sided mesh, in front");
    auto one_sided = std::make_shared<MeshEmitter>();
    one_sided->add(Vec3(-1, 2, -1), Vec3(1, 2, -1), Vec3(1, 2, 1), Vec3(1.0f));
    mesh.mesh = one_sided;
    LightSample s;
    EXPECT_FALSE(sample_light(mesh, behind, glm::vec2(0.3f, 0.4f), s));
    EXPECT_EQ(light_pdf(mesh, behind, Vec3(0, -1, 0)), 0.0f);
}

TEST(LightPdf, ThePunctualLightsAreDeltas) {
    for (const Light& light :
         {Light(PointLight{}), Light(SpotLight{}), Light(DirectionalLight{})}) {
        EXPECT_TRUE(light_is_delta(light));
        EXPECT_EQ(light_pdf(light, Vec3(0), Vec3(0, 1, 0)), 0.0f);
    }
}

// A shading point every default-constructed light reaches: below the origin, where the point
// and spot lights sit (inside the spot's default 45° cone about −y), in front of the default
// disk (at the origin, emitting toward −y).
const Vec3 kBelowTheLights(0.3f, -2.0f, 0.1f);

TEST(LightRegistry, EveryKindSamplesWhatItsPdfSays) {
    for_each_light([](auto defaults) {
        using L = decltype(defaults);
        const Light light = defaults;
        const std::string name = L::kName;
        EXPECT_EQ(light_is_delta(light), L::kDelta) << name;
        int sampled = 0;
        for (int i = 0; i < 16; ++i) {
            for (int j = 0; j < 16; ++j) {
                const glm::vec2 u((i + 0.37f) / 16, (j + 0.61f) / 16);
                LightSample s;
                if (!sample_light(light, kBelowTheLights, u, s)) continue;
                ++sampled;
                EXPECT_NEAR(glm::length(s.direction), 1.0f, 1e-5f) << name;
                EXPECT_GT(s.pdf, 0.0f) << name;
                if (L::kDelta) {
                    // One direction per shading point, which no other direction has.
                    EXPECT_EQ(s.pdf, 1.0f) << name;
                    EXPECT_EQ(light_pdf(light, kBelowTheLights, s.direction), 0.0f) << name;
                } else {
                    EXPECT_NEAR(light_pdf(light, kBelowTheLights, s.direction), s.pdf,
                                2e-3f * s.pdf)
                        << name;
                }
            }
        }
        EXPECT_EQ(sampled, 256) << name << " refused samples at a point it lights";
        if (!L::kDelta) {
            EXPECT_NEAR(integral_over_sphere(light, kBelowTheLights), 1.0, 0.01) << name;
        }
    });
}

TEST(LightRegistry, EveryKindEmitsWhatItsSamplesCarry) {
    // A ray along a sampled direction that reaches the light at the sampled point (facing the
    // ray) carries back the sample's radiance; the delta lights, which no ray reaches, nothing.
    for_each_light([](auto defaults) {
        using L = decltype(defaults);
        const Light light = defaults;
        const std::string name = L::kName;
        for (int i = 0; i < 8; ++i) {
            LightSample s;
            const glm::vec2 u((i + 0.5f) / 8, (7 - i + 0.25f) / 8);
            ASSERT_TRUE(sample_light(light, kBelowTheLights, u, s)) << name;
            EmitterPoint at;
            if (std::isfinite(s.distance)) at.position = kBelowTheLights + s.distance * s.direction;
            at.normal = -s.direction;
            at.radiance = s.radiance;
            const Vec3 emitted = light_emitted(light, s.direction, at);
            if (L::kDelta) {
                EXPECT_EQ(emitted, Vec3(0.0f)) << name;
                EXPECT_EQ(light_pdf_at(light, kBelowTheLights, s.direction, at), 0.0f) << name;
            } else {
                EXPECT_GT(glm::length(s.radiance), 0.0f) << name;
                EXPECT_NEAR(emitted.x, s.radiance.x, 1e-6f * s.radiance.x) << name;
                EXPECT_NEAR(emitted.y, s.radiance.y, 1e-6f * s.radiance.y) << name;
                EXPECT_NEAR(emitted.z, s.radiance.z, 1e-6f * s.radiance.z) << name;
                EXPECT_NEAR(light_pdf_at(light, kBelowTheLights, s.direction, at), s.pdf,
                            2e-3f * s.pdf)
                    << name;
            }
        }
    });
}

TEST(LightRegistry, EveryKindDescribesItself) {
    // `rayo info`, --stats and the Python module's Scene.lights print kName and describe().
    std::vector<std::string> names;
    for_each_light([&](auto defaults) {
        using L = decltype(defaults);
        std::ostringstream text;
        defaults.describe(text);
        EXPECT_FALSE(text.str().empty()) << L::kName;
        EXPECT_EQ(text.str().front(), ' ') << L::kName << ": " << text.str();
        ASSERT_NE(std::string(L::kName), "");
        for (const std::string& n : names) EXPECT_NE(n, L::kName) << "two kinds of one name";
        names.push_back(L::kName);
    });
    EXPECT_EQ(names.size(), std::variant_size_v<Light>);
}

TEST(AreaLight, EmitsFromItsFrontOnly) {
    AreaLight disk;  // at the origin, emitting toward −y
    disk.intensity = 2.5f;
    const EmitterPoint at{Vec3(0.0f), Vec3(0, -1, 0), Vec3(0.0f)};
    expect_vec_near(disk.emitted(Vec3(0, 1, 0), at), Vec3(2.5f), 0.0f);   // arriving from below
    expect_vec_near(disk.emitted(Vec3(0, -1, 0), at), Vec3(0.0f), 0.0f);  // from above: its back
    AreaLight mesh;
    mesh.shape = AreaLight::Shape::Mesh;  // the triangle's own radiance, not color·intensity
    const EmitterPoint on_triangle{Vec3(0.0f), Vec3(0, 0, 1), Vec3(0.5f, 1.0f, 2.0f)};
    expect_vec_near(mesh.emitted(glm::normalize(Vec3(0.3f, 0, -1)), on_triangle),
                    Vec3(0.5f, 1.0f, 2.0f), 0.0f);
}

}  // namespace
}  // namespace rayo
