// The material-to-scattering mapping (shading/scattering/material_bsdf.h): which lobes a
// material's coefficients become, that the sum evaluates as its lobes do, and that its energy
// (a Monte Carlo estimate through sample()) is the lobes' albedos.
#include "shading/scattering/material_bsdf.h"

#include <gtest/gtest.h>

#include "shading/metallic_roughness.h"

namespace rayo {
namespace {

// ∫ f·|cos θi| dω for `wo`, as the mean of value·|cos θi|/pdf over an n×n grid of u.
Vec3 albedo_by_sampling(const Bsdf& bsdf, const Vec3& wo, int n = 400) {
    Vec3 sum(0.0f);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const glm::vec2 u((i + 0.5f) / n, (j + 0.5f) / n);
            ScatterSample s;
            if (bsdf.sample(wo, u, s) && s.pdf > 0.0f) sum += s.value * std::abs(s.wi.z) / s.pdf;
        }
    }
    return sum / static_cast<float>(n * n);
}

TEST(MaterialBsdf, APhongMaterialIsLambertPlusTheNormalisedPhongLobe) {
    SurfaceCoefficients m;
    m.kd = Vec3(0.5f, 0.4f, 0.3f);
    m.ks = Vec3(0.3f);
    m.shininess = 20.0f;
    const Bsdf bsdf = material_bsdf(m);
    ASSERT_EQ(bsdf.size(), 2);
    const Vec3 wo = glm::normalize(Vec3(0.3f, 0.1f, 1.0f));
    const Vec3 wi = glm::normalize(Vec3(-0.2f, 0.4f, 0.8f));
    const Vec3 expected = Lambert(m.kd).eval(wo, wi) + ModifiedPhong(m.ks, 20.0f).eval(wo, wi);
    EXPECT_NEAR(bsdf.eval(wo, wi).x, expected.x, 1e-6f);
    EXPECT_NEAR(bsdf.eval(wo, wi).z, expected.z, 1e-6f);
    // At normal incidence the modified Phong lobe reflects exactly ks: kd + ks in all.
    const Vec3 albedo = albedo_by_sampling(bsdf, Vec3(0, 0, 1));
    EXPECT_NEAR(albedo.x, 0.8f, 0.01f);
    EXPECT_NEAR(albedo.z, 0.6f, 0.01f);
}

TEST(MaterialBsdf, BlinnMaterialsGetTheBlinnLobe) {
    SurfaceCoefficients m;
    m.kd = Vec3(0.0f);
    m.ks = Vec3(1.0f);
    m.shininess = 50.0f;
    m.specular_model = SpecularModel::Blinn;
    const Bsdf bsdf = material_bsdf(m);
    ASSERT_EQ(bsdf.size(), 1);
    const Vec3 wo = glm::normalize(Vec3(0.2f, 0.0f, 1.0f)), wi = glm::normalize(Vec3(-0.2f, 0, 1));
    EXPECT_EQ(bsdf.eval(wo, wi), BlinnPhong(m.ks, 50.0f).eval(wo, wi));
}

TEST(MaterialBsdf, GltfMaterialsSampleTheMetallicRoughnessModel) {
    SurfaceCoefficients m;
    apply_metallic_roughness(m, Vec3(0.8f, 0.5f, 0.2f), 0.3f, 0.6);
    const Bsdf bsdf = material_bsdf(m);
    ASSERT_EQ(bsdf.size(), 1);
    const MetallicRoughnessBsdf reference(Vec3(0.8f, 0.5f, 0.2f), 0.3f, 0.6f);
    const Vec3 wo = glm::normalize(Vec3(0.4f, -0.1f, 1.0f)),
               wi = glm::normalize(Vec3(-0.3f, 0.2f, 1));
    EXPECT_EQ(bsdf.eval(wo, wi), reference.eval(wo, wi));
    EXPECT_EQ(bsdf.pdf(wo, wi), reference.pdf(wo, wi));
}

TEST(MaterialBsdf, GlassIsTheDielectricAndMirrorsTheMirror) {
    SurfaceCoefficients glass;
    glass.kd = Vec3(0.0f);
    glass.transmit = Vec3(1.0f);
    glass.ior = 1.5f;
    const Bsdf g = material_bsdf(glass);
    ASSERT_EQ(g.size(), 1);
    // R + T = 1 for the smooth dielectric, at any angle.
    EXPECT_NEAR(albedo_by_sampling(g, glm::normalize(Vec3(0.5f, 0, 1)), 100).x, 1.0f, 1e-4f);
    ScatterSample s;
    ASSERT_TRUE(g.sample(Vec3(0, 0, 1), glm::vec2(0.9f, 0.5f), s));
    EXPECT_TRUE(s.delta);

    SurfaceCoefficients mirror;
    mirror.kd = Vec3(0.2f);
    mirror.reflect = Vec3(0.7f);
    const Bsdf m = material_bsdf(mirror);
    ASSERT_EQ(m.size(), 2);
    EXPECT_NEAR(albedo_by_sampling(m, glm::normalize(Vec3(0.3f, 0.2f, 1))).y, 0.9f, 0.01f);
}

TEST(MaterialBsdf, TranslucencyTransmitsDiffusely) {
    SurfaceCoefficients leaf;
    leaf.kd = Vec3(0.3f);
    leaf.translucency = Vec3(0.4f);
    const Bsdf bsdf = material_bsdf(leaf);
    ASSERT_EQ(bsdf.size(), 2);
    const Vec3 wo(0, 0, 1);
    EXPECT_NEAR(bsdf.eval(wo, Vec3(0, 0, -1)).x, 0.4f / kPi, 1e-6f);
    EXPECT_NEAR(albedo_by_sampling(bsdf, wo).x, 0.7f, 0.01f);
}

}  // namespace
}  // namespace rayo
