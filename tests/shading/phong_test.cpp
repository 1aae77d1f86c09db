// Tests of the Phong local model (shading/phong.h, seed 000 eqs. [18]-[28]) and of the light
// attenuation factors (shading/light.h, seed 000 and seed 003 eq. 2.8), against hand-computed
// values.
#include "shading/phong.h"

#include <gtest/gtest.h>

#include <cmath>

#include "shading/light.h"
#include "shading/material.h"
#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec_near;

// The geometry of the hand computations:
//   N = (0,0,1), L = (1,0,1)/√2 (light 45° off the normal), V = (0,0,1) (eye straight above).
//   N·L = 1/√2 = 0.707107.
//   R = 2(N·L)N − L = (0,0,√2) − (1,0,1)/√2 = (−1,0,1)/√2, so V·R = 1/√2 = 0.707107 (φ = 45°).
//   H = (L+V)/|L+V| bisects L and V, 22.5° off N: N·H = cos 22.5° = 0.923880 (eq. [27]: half
//   the angle of V·R).
//   With n = 10: (V·R)^10 = (1/√2)^10 = 1/32 = 0.03125; (N·H)^10 = 0.923880^10 = 0.453058.
// Per-channel coefficients Kd = (0.8, 0.5, 0.2), Ks = (0.5, 0.25, 1.0):
//   Lambert Kd(N·L) = (0.565685, 0.353553, 0.141421)
//   Phong   Ks(V·R)^n = (0.015625, 0.0078125, 0.03125)
//   Blinn   Ks(N·H)^n = (0.226529, 0.113264, 0.453058)
const Vec3 kNormal(0.0f, 0.0f, 1.0f);
const Vec3 kToLight = glm::normalize(Vec3(1.0f, 0.0f, 1.0f));
const Vec3 kToEye(0.0f, 0.0f, 1.0f);

Material test_material(SpecularModel model) {
    Material m;
    m.kd = Vec3(0.8f, 0.5f, 0.2f);
    m.ks = Vec3(0.5f, 0.25f, 1.0f);
    m.shininess = 10.0f;
    m.specular_model = model;
    return m;
}

TEST(Phong, LambertTermPerChannel) {
    // seed 000 eqs. [18], [22]: Kd·(N·L) per channel.
    const Vec3 d = lambert_term(test_material(SpecularModel::Phong), kNormal, kToLight);
    expect_vec_near(d, Vec3(0.565685f, 0.353553f, 0.141421f), 1e-6f);
    // Head-on: N·L = 1 gives Kd itself.
    expect_vec_near(lambert_term(test_material(SpecularModel::Phong), kNormal, kNormal),
                    Vec3(0.8f, 0.5f, 0.2f), 0.0f);
}

TEST(Phong, PhongSpecularVDotRToTheN) {
    // seed 000 eqs. [23]-[24]: Ks·(V·R)^n.
    const Vec3 s = specular_term(test_material(SpecularModel::Phong), kNormal, kToLight, kToEye);
    expect_vec_near(s, Vec3(0.015625f, 0.0078125f, 0.03125f), 1e-6f);
    // The eye on the mirror direction R sees the full Ks.
    const Vec3 mirror = glm::normalize(Vec3(-1.0f, 0.0f, 1.0f));
    expect_vec_near(specular_term(test_material(SpecularModel::Phong), kNormal, kToLight, mirror),
                    Vec3(0.5f, 0.25f, 1.0f), 1e-6f);
}

TEST(Phong, BlinnSpecularNDotHToTheN) {
    // seed 000 eq. [28]: Ks·(N·H)^n; the highlight is wider than Phong's for the same n.
    const Vec3 s = specular_term(test_material(SpecularModel::Blinn), kNormal, kToLight, kToEye);
    expect_vec_near(s, Vec3(0.226529f, 0.113264f, 0.453058f), 1e-6f);
    // With V = L the halfway vector is L itself: (N·L)^10 = (1/√2)^10 = 1/32.
    expect_vec_near(specular_term(test_material(SpecularModel::Blinn), kNormal, kToLight, kToLight),
                    Vec3(0.5f, 0.25f, 1.0f) / 32.0f, 1e-6f);
}

TEST(Phong, DirectLightingSumsDiffuseAndSpecularTimesTheLight) {
    // seed 000 eq. [24]: Ii·[Kd(N·L) + Ks(V·R)^n] with a coloured light Ii = (1, 0.5, 2):
    // (1·(0.565685 + 0.015625), 0.5·(0.353553 + 0.0078125), 2·(0.141421 + 0.03125))
    // = (0.581310, 0.180683, 0.345343).
    const Vec3 light(1.0f, 0.5f, 2.0f);
    expect_vec_near(
        phong_direct(test_material(SpecularModel::Phong), kNormal, kToLight, kToEye, light),
        Vec3(0.581310f, 0.180683f, 0.345343f), 2e-6f);
    // eq. [28] with the Blinn term: (0.565685 + 0.226529, 0.5·(0.353553 + 0.113264),
    // 2·(0.141421 + 0.453058)) = (0.792214, 0.233409, 1.188958).
    expect_vec_near(
        phong_direct(test_material(SpecularModel::Blinn), kNormal, kToLight, kToEye, light),
        Vec3(0.792214f, 0.233409f, 1.188958f), 2e-6f);
}

TEST(Phong, LightBelowTheSurfaceContributesNothing) {
    for (SpecularModel model : {SpecularModel::Phong, SpecularModel::Blinn}) {
        const Material m = test_material(model);
        const Vec3 below = glm::normalize(Vec3(1.0f, 0.0f, -1.0f));
        expect_vec_near(lambert_term(m, kNormal, below), Vec3(0.0f), 0.0f);
        expect_vec_near(specular_term(m, kNormal, below, kToEye), Vec3(0.0f), 0.0f);
        // Even with the eye on the below-surface mirror direction, no highlight.
        expect_vec_near(specular_term(m, kNormal, below, glm::normalize(Vec3(-1.0f, 0.0f, -1.0f))),
                        Vec3(0.0f), 0.0f);
        expect_vec_near(phong_direct(m, kNormal, below, kToEye, Vec3(1.0f)), Vec3(0.0f), 0.0f);
        // Grazing light (N·L = 0) also gives nothing (eq. [18]: only for N·L > 0).
        expect_vec_near(phong_direct(m, kNormal, Vec3(1.0f, 0.0f, 0.0f), kToEye, Vec3(1.0f)),
                        Vec3(0.0f), 0.0f);
    }
}

TEST(Phong, EyeBehindTheMirrorDirectionGetsNoPhongHighlight) {
    // V = (1,0,0.2)/|…| is on the light's side: V·R = (−1 + 0.2)/(√2·1.0198) < 0, so the Phong
    // term is 0 and only the diffuse term remains. Blinn's N·H stays positive (H lies between
    // two vectors above the surface), so it still gives a (small) highlight.
    const Vec3 eye = glm::normalize(Vec3(1.0f, 0.0f, 0.2f));
    const Material phong = test_material(SpecularModel::Phong);
    expect_vec_near(specular_term(phong, kNormal, kToLight, eye), Vec3(0.0f), 0.0f);
    expect_vec_near(phong_direct(phong, kNormal, kToLight, eye, Vec3(1.0f)),
                    Vec3(0.565685f, 0.353553f, 0.141421f), 1e-6f);
    // Blinn: H = normalize(L + V); N·H = cos of the angle of H from N.
    const Vec3 h = glm::normalize(kToLight + eye);
    const float expected = std::pow(h.z, 10.0f);
    const Vec3 blinn = specular_term(test_material(SpecularModel::Blinn), kNormal, kToLight, eye);
    expect_vec_near(blinn, Vec3(0.5f, 0.25f, 1.0f) * expected, 1e-6f);
    EXPECT_GT(blinn.x, 0.0f);
}

TEST(Phong, SeedRedSurfaceExampleIsOutOfRange) {
    // seed 000 eq. [21]/[22]: Kd = Ka = (1,0,0), Ia = 0.5, Ii = 1, N·L = 1
    // -> I = Ka·Ia + Ii·Kd·(N·L) = (0.5 + 1, 0, 0) = (1.5, 0, 0).
    Material m;
    m.ka = Vec3(1.0f, 0.0f, 0.0f);
    m.kd = Vec3(1.0f, 0.0f, 0.0f);
    m.ks = Vec3(0.0f);
    const float ambient = 0.5f;
    const Vec3 i = m.ka * ambient + phong_direct(m, kNormal, kNormal, kToEye, Vec3(1.0f));
    expect_vec_near(i, Vec3(1.5f, 0.0f, 0.0f), 0.0f);
}

TEST(Phong, AttenuationFactors) {
    Attenuation none;
    EXPECT_EQ(none.factor(0.0f), 1.0f);
    EXPECT_EQ(none.factor(123.0f), 1.0f);

    // seed 000: f(d) = 1/(d + d0). d0 = 2, d = 3 -> 0.2. Not clamped: d0 = 0.5, d = 0.25 ->
    // 1/0.75 = 1.333333.
    Attenuation linear;
    linear.kind = Attenuation::Kind::Linear;
    linear.d0 = 2.0f;
    EXPECT_FLOAT_EQ(linear.factor(3.0f), 0.2f);
    EXPECT_FLOAT_EQ(linear.factor(0.0f), 0.5f);
    linear.d0 = 0.5f;
    EXPECT_FLOAT_EQ(linear.factor(0.25f), 1.0f / 0.75f);

    // seed 003 eq. 2.8: f(d) = min(1, 1/(a0 + a1·d + a2·d²)).
    Attenuation quadratic;
    quadratic.kind = Attenuation::Kind::Quadratic;
    quadratic.a0 = 1.0f;
    quadratic.a1 = 0.5f;
    quadratic.a2 = 0.25f;
    EXPECT_FLOAT_EQ(quadratic.factor(2.0f), 1.0f / 3.0f);  // 1 + 1 + 1
    EXPECT_FLOAT_EQ(quadratic.factor(4.0f), 1.0f / 7.0f);  // 1 + 2 + 4
    EXPECT_FLOAT_EQ(quadratic.factor(0.0f), 1.0f);         // 1/a0
    // The clamp: a pure 1/d² law is above 1 close to the light.
    quadratic.a0 = 0.0f;
    quadratic.a1 = 0.0f;
    quadratic.a2 = 1.0f;
    EXPECT_FLOAT_EQ(quadratic.factor(2.0f), 0.25f);
    EXPECT_FLOAT_EQ(quadratic.factor(1.0f), 1.0f);
    EXPECT_EQ(quadratic.factor(0.5f), 1.0f);  // 1/0.25 = 4 -> 1
    EXPECT_EQ(quadratic.factor(0.0f), 1.0f);  // 1/0 = inf -> 1
    // a0 below 1 clamps at d = 0 too: min(1, 1/0.25) = 1.
    quadratic.a0 = 0.25f;
    quadratic.a2 = 0.0f;
    EXPECT_EQ(quadratic.factor(0.0f), 1.0f);
}

}  // namespace
}  // namespace rayo
