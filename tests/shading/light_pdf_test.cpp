// The lights' densities for sampling integrators (shading/light.h light_pdf): for every light
// with an extent, pdf(point, direction) is the solid-angle density with which sample() gives the
// direction (the same number sample() reports, for its own directions) and integrates to 1 over
// the sphere of directions; the point, spot and directional lights are deltas with no density.
#include <gtest/gtest.h>

#include <memory>

#include "shading/light.h"

namespace rayo {
namespace {

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

TEST(LightPdf, ThePunctualLightsAreDeltas) {
    for (const Light& light :
         {Light(PointLight{}), Light(SpotLight{}), Light(DirectionalLight{})}) {
        EXPECT_TRUE(light_is_delta(light));
        EXPECT_EQ(light_pdf(light, Vec3(0), Vec3(0, 1, 0)), 0.0f);
    }
}

}  // namespace
}  // namespace rayo
