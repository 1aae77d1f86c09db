// Tests of perfect specular reflection and Snell refraction (shading/optics.h, seed 001):
// closed-form reflections, Snell's law at several angles, total internal reflection around the
// critical angle.
#include "shading/optics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/test_helpers.h"

namespace rayo {
namespace {

using rayo_test::expect_vec_near;

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// Incident direction at `degrees` from the normal (0,1,0), travelling down in the xy plane.
Vec3 incident_at(double degrees) {
    return Vec3(float(std::sin(degrees * kDegree)), float(-std::cos(degrees * kDegree)), 0.0f);
}

TEST(Optics, ReflectMirrorsAboutTheNormal) {
    const Vec3 n(0.0f, 1.0f, 0.0f);
    // seed 001: R = I − 2(I·N)N. At 45°: (1,−1,0)/√2 -> (1,1,0)/√2.
    const float h = std::sqrt(0.5f);
    expect_vec_near(reflect(Vec3(h, -h, 0.0f), n), Vec3(h, h, 0.0f), 1e-7f);
    // Normal incidence reverses the ray.
    expect_vec_near(reflect(Vec3(0.0f, -1.0f, 0.0f), n), Vec3(0.0f, 1.0f, 0.0f), 0.0f);
    // A general case: I = (2,−3,6)/7 on N = (0,0,−1) (N faces the incident side, N·I < 0):
    // I·N = −6/7, R = I − 2(−6/7)N = (2,−3,6)/7 + (12/7)(0,0,−1) = (2,−3,−6)/7.
    expect_vec_near(reflect(Vec3(2.0f, -3.0f, 6.0f) / 7.0f, Vec3(0.0f, 0.0f, -1.0f)),
                    Vec3(2.0f, -3.0f, -6.0f) / 7.0f, 1e-7f);
    // Reflection keeps unit length and the angle: R·N = −I·N.
    const Vec3 i = glm::normalize(Vec3(0.3f, -0.8f, 0.52f));
    const Vec3 r = reflect(i, n);
    EXPECT_NEAR(glm::length(r), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(r, n), -glm::dot(i, n), 1e-6f);
}

TEST(Optics, RefractAtNormalIncidenceGoesStraightThrough) {
    const Vec3 n(0.0f, 1.0f, 0.0f);
    for (float n21 : {1.0f, 1.33f, 1.5f, 1.0f / 1.5f}) {
        // seed 001 with −I·N = 1: T = I/n21 + (1/n21 − 1)·N = (0,−1,0).
        const auto t = refract(Vec3(0.0f, -1.0f, 0.0f), n, n21);
        ASSERT_TRUE(t.has_value()) << n21;
        expect_vec_near(*t, Vec3(0.0f, -1.0f, 0.0f), 1e-6f);
    }
}

TEST(Optics, SnellsLawAtSeveralAngles) {
    const Vec3 n(0.0f, 1.0f, 0.0f);
    for (float n21 : {1.33f, 1.5f}) {  // water and glass, from air
        for (double degrees : {10.0, 30.0, 45.0, 60.0, 80.0, 89.0}) {
            SCOPED_TRACE(testing::Message() << "n21 " << n21 << " at " << degrees << "°");
            const Vec3 i = incident_at(degrees);
            const auto t = refract(i, n, n21);
            ASSERT_TRUE(t.has_value());
            EXPECT_NEAR(glm::length(*t), 1.0f, 1e-6f);
            EXPECT_LT(t->y, 0.0f);           // goes into the surface
            EXPECT_GT(t->x, 0.0f);           // on the far side of the normal from I
            EXPECT_NEAR(t->z, 0.0f, 1e-7f);  // in the plane of incidence
            // Snell: sin i = n21 · sin t, with sin t the tangential component of unit T.
            const double sin_t = t->x;
            EXPECT_NEAR(std::sin(degrees * kDegree), n21 * sin_t, 2e-6);
            // The expected angle itself: t = asin(sin i / n21); e.g. 45° into n = 1.5 gives
            // 28.1255°.
            EXPECT_NEAR(std::acos(-double(t->y)) / kDegree,
                        std::asin(std::sin(degrees * kDegree) / n21) / kDegree, 1e-3);
        }
    }
    // One hand-checked value: 45° into glass, sin t = 0.707107/1.5 = 0.471405, t = 28.1255°.
    const auto t = refract(incident_at(45.0), n, 1.5f);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(t->x, 0.471405f, 1e-6f);
    EXPECT_NEAR(std::acos(-double(t->y)) / kDegree, 28.1255, 1e-3);
}

TEST(Optics, SnellsLawLeavingTheDenserMedium) {
    // From inside glass to air (n21 = 1/1.5) below the critical angle: 20° -> asin(1.5 sin 20°)
    // = 30.8659°.
    const Vec3 n(0.0f, 1.0f, 0.0f);
    const auto t = refract(incident_at(20.0), n, 1.0f / 1.5f);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(t->x, 1.5 * std::sin(20.0 * kDegree), 1e-6);
    EXPECT_NEAR(std::acos(-double(t->y)) / kDegree, 30.8659, 1e-3);
}

TEST(Optics, TotalInternalReflectionPastTheCriticalAngle) {
    const Vec3 n(0.0f, 1.0f, 0.0f);
    const float n21 = 1.0f / 1.5f;  // glass -> air; critical angle asin(1/1.5) = 41.8103°
    // Just past it: the radicand 1 + (cos² i − 1)/n21² = 1 − 2.25 sin² i is negative.
    EXPECT_FALSE(refract(incident_at(41.91), n, n21).has_value());
    EXPECT_FALSE(refract(incident_at(60.0), n, n21).has_value());
    EXPECT_FALSE(refract(incident_at(89.0), n, n21).has_value());
    // Just below it (41.71°): sin t = 1.5 sin 41.71° = 0.998041, t = 86.413°: a grazing ray.
    const auto t = refract(incident_at(41.71), n, n21);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(glm::length(*t), 1.0f, 1e-5f);
    EXPECT_NEAR(t->x, 1.5 * std::sin(41.71 * kDegree), 1e-5);
    const double angle = std::acos(-double(t->y)) / kDegree;
    EXPECT_NEAR(angle, std::asin(1.5 * std::sin(41.71 * kDegree)) / kDegree, 0.05);
    EXPECT_GT(angle, 85.0);
    EXPECT_LT(angle, 90.0);
    // Water (n = 1.33) to air: critical angle asin(1/1.33) = 48.753°.
    EXPECT_TRUE(refract(incident_at(48.65), n, 1.0f / 1.33f).has_value());
    EXPECT_FALSE(refract(incident_at(48.85), n, 1.0f / 1.33f).has_value());
}

TEST(Optics, CriticalAngle) {
    // asin(1/1.5) = 41.8103149°; asin(1/1.33) = 48.7535°.
    EXPECT_NEAR(critical_angle(1.0f / 1.5f) / kDegree, 41.81, 0.01);
    EXPECT_NEAR(critical_angle(1.0f / 1.5f) / kDegree, 41.810315, 1e-4);
    EXPECT_NEAR(critical_angle(1.0f / 1.33f) / kDegree, 48.7535, 1e-3);
}

}  // namespace
}  // namespace rayo

namespace rayo {
namespace {

// The Fresnel transmittance from the amplitude transmission coefficients (Hecht, Optics §4.6):
// ts = 2 n1 cos θi/(n1 cos θi + n2 cos θt), tp = 2 n1 cos θi/(n2 cos θi + n1 cos θt),
// T = (n2 cos θt)/(n1 cos θi)·(ts² + tp²)/2. Independent of fresnel_reflectance's formula.
double fresnel_transmittance(double degrees, double n1, double n2) {
    const double cos_i = std::cos(degrees * kDegree);
    const double sin_t = n1 / n2 * std::sin(degrees * kDegree);
    if (sin_t >= 1.0) return 0.0;
    const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
    const double ts = 2.0 * n1 * cos_i / (n1 * cos_i + n2 * cos_t);
    const double tp = 2.0 * n1 * cos_i / (n2 * cos_i + n1 * cos_t);
    return n2 * cos_t / (n1 * cos_i) * 0.5 * (ts * ts + tp * tp);
}

float reflectance_at(double degrees, float n21) {
    return fresnel_reflectance(static_cast<float>(std::cos(degrees * kDegree)), n21);
}

TEST(Fresnel, NormalIncidenceOnGlassReflectsFourPercent) {
    // ((n − 1)/(n + 1))² = (0.5/2.5)² = 0.04, from either side.
    EXPECT_NEAR(fresnel_reflectance(1.0f, 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(fresnel_reflectance(1.0f, 1.0f / 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(fresnel_reflectance(1.0f, 1.33f), std::pow(0.33f / 2.33f, 2.0f), 1e-6f);  // water
}

TEST(Fresnel, TotalBeyondTheCriticalAngle) {
    const float n21 = 1.0f / 1.5f;                           // glass to air
    const double critical = std::asin(1.0 / 1.5) / kDegree;  // 41.81°
    for (double d : {critical + 0.01, 50.0, 70.0, 89.9}) {
        EXPECT_EQ(reflectance_at(d, n21), 1.0f) << d << " degrees";
    }
    EXPECT_LT(reflectance_at(critical - 0.5, n21), 1.0f);
    EXPECT_GT(reflectance_at(critical - 0.5, n21), 0.2f);  // rises steeply toward it
}

TEST(Fresnel, ReflectancePlusTransmittanceIsOne) {
    for (double n : {1.33, 1.5, 2.4}) {
        for (double d = 0.0; d < 90.0; d += 7.5) {
            const double r_in = reflectance_at(d, static_cast<float>(n));
            EXPECT_NEAR(r_in + fresnel_transmittance(d, 1.0, n), 1.0, 2e-6) << n << " " << d;
            const double r_out = reflectance_at(d, static_cast<float>(1.0 / n));
            EXPECT_NEAR(r_out + fresnel_transmittance(d, n, 1.0), 1.0, 2e-6) << n << " " << d;
        }
    }
}

TEST(Fresnel, BrewsterAngleReflectsOnlyTheSPolarization) {
    // At tan θB = n the p amplitude vanishes and rs = −(n² − 1)/(n² + 1): R = rs²/2.
    const double n = 1.5;
    const double brewster = std::atan(n) / kDegree;
    const double rs = (n * n - 1.0) / (n * n + 1.0);
    EXPECT_NEAR(reflectance_at(brewster, 1.5f), 0.5 * rs * rs, 1e-6);
    // Grazing incidence reflects everything; the reflectance rises monotonically toward it.
    EXPECT_NEAR(reflectance_at(90.0, 1.5f), 1.0f, 1e-6f);
    EXPECT_LT(reflectance_at(60.0, 1.5f), reflectance_at(80.0, 1.5f));
}

}  // namespace
}  // namespace rayo
