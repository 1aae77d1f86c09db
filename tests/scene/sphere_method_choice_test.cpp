// `auto`'s choice of sphere method and precision, and the icosphere level for an error budget.
// Every branch of choose_sphere_method answers "user", so the tests assert what the choice
// decides and could get wrong: which branch (and reason) a scene built for it takes, the math it
// keeps, and the numbers it reports against values computed here from the documented model.
#include "apps/scene/sphere_method_choice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "core/shapes/icosphere.h"

namespace rayo {
namespace {

SceneDescription one_sphere_scene(const Vec3& offset, float radius, float distance) {
    SceneDescription d;
    d.scene.camera.eye = offset + Vec3(0, 0, distance);
    d.scene.camera.look_at = offset;
    d.scene.camera.vfov_degrees = 45.0f;
    d.scene.camera.width = d.scene.camera.height = 512;
    d.scene.shapes.of<Sphere>().push_back({offset, radius, 0});
    d.shading.materials.emplace_back();
    return d;
}

SphereChoice choose(const SceneDescription& d) {
    return choose_sphere_method(d, Camera::create(d.scene.camera));
}

// The error model `auto` uses (docs/sphere-methods.md "auto"; sphere_method_choice.cpp): float
// coordinates of magnitude M = max(|centre|∞, |eye|∞) move a silhouette by 4·ε·M world units
// (ε = 2^-23), seen at `distance` through pixels of angle 2·tan(vfov/2)/height. In double.
double pixel_angle(double vfov_degrees, int height) {
    return 2.0 * std::tan(vfov_degrees * 3.14159265358979323846 / 360.0) / height;
}
double float_error_px(double magnitude, double distance) {
    return 4.0 * std::ldexp(1.0, -23) * magnitude / (distance * pixel_angle(45.0, 512));
}

// The numbers of a "within budget" reason: float error, budget, mesh level, largest radius.
struct WithinReason {
    double error_px = -1, budget = -1, radius_px = -1;
    int level = -1;
};
WithinReason parse_within(const std::string& reason) {
    static const std::regex pattern(
        R"(^user/stable: analytic and exact \(float error <= (\S+) px <= budget (\S+) px\); )"
        R"(a mesh would need level (\d+) for the largest sphere \((\S+) px radius\)$)");
    std::smatch m;
    WithinReason r;
    if (!std::regex_match(reason, m, pattern)) {
        ADD_FAILURE() << "not a within-budget reason: " << reason;
        return r;
    }
    r.error_px = std::stod(m[1]);
    r.budget = std::stod(m[2]);
    r.level = std::stoi(m[3]);
    r.radius_px = std::stod(m[4]);
    return r;
}

// The numbers of a "beyond float" reason: float error and budget.
std::pair<double, double> parse_beyond(const std::string& reason) {
    static const std::regex pattern(
        R"(^user/stable: beyond float's resolution: coordinates this large put silhouettes )"
        R"(up to (\S+) px off \(> budget (\S+) px\) for every method, double included; )"
        R"(move the scene near the origin$)");
    std::smatch m;
    if (!std::regex_match(reason, m, pattern)) {
        ADD_FAILURE() << "not a beyond-float reason: " << reason;
        return {-1.0, -1.0};
    }
    return {std::stod(m[1]), std::stod(m[2])};
}

// The reason prints 6 significant digits; the choice computes in float.
void expect_relative(double actual, double expected, double tolerance = 2e-5) {
    EXPECT_NEAR(actual, expected, tolerance * expected) << "expected " << expected;
}

// A unit sphere 5 units in front of the eye, near the origin: M = 5, distance 5, projected
// radius 1/(5·pixel angle) = 123.607 px. Level 3 facets lie 123.607 × 0.0045284 = 0.56 px inside
// (> 0.5), level 4 ones 123.607 × 0.0011379 = 0.14 px: the reason must quote level 4.
TEST(SphereMethodChoice, WithinBudgetReportsTheFloatErrorAndTheMeshLevel) {
    const SceneDescription d = one_sphere_scene(Vec3(0), 1.0f, 5.0f);
    const SphereChoice c = choose(d);
    EXPECT_EQ(c.spheres.method, SphereMethod::User);
    EXPECT_EQ(c.math, SphereMath::Stable);
    const double error = float_error_px(5.0, 5.0);  // 2.947e-4 px
    expect_relative(c.worst_float_error_px, error, 1e-5);
    const WithinReason r = parse_within(c.reason);
    expect_relative(r.error_px, error);
    EXPECT_EQ(r.budget, 0.5);
    EXPECT_EQ(r.level, 4);
    expect_relative(r.radius_px, 1.0 / (5.0 * pixel_angle(45.0, 512)));
    EXPECT_NEAR(r.radius_px, 123.607, 2e-3);  // printed to 6 digits from a float
}

// With the eye inside the sphere the distance counts as the radius: a radius-10 sphere around
// an eye 5 from its centre projects to 10/(10·pixel angle) = 618.03 px, which needs level 5
// (618.03 × 0.0011379 = 0.70 > 0.5; × 0.00028482 = 0.18), and M = 5 at distance 10.
TEST(SphereMethodChoice, EyeInsideASphereMeasuresFromItsRadius) {
    const SceneDescription d = one_sphere_scene(Vec3(0), 10.0f, 5.0f);
    const SphereChoice c = choose(d);
    const WithinReason r = parse_within(c.reason);
    expect_relative(c.worst_float_error_px, float_error_px(5.0, 10.0), 1e-5);
    EXPECT_EQ(r.level, 5);
    expect_relative(r.radius_px, 1.0 / pixel_angle(45.0, 512));
}

// The worst error and the largest sphere come from different spheres here, in either order:
// a small sphere 1 unit from the eye (error 5× the other's) and the unit sphere at 5 (the
// larger one on screen, 123.607 px against 0.1/1/pixel angle = 61.8 px).
TEST(SphereMethodChoice, ReportsTheWorstErrorAndLargestSphereOverAllSpheres) {
    for (bool small_first : {true, false}) {
        SceneDescription d = one_sphere_scene(Vec3(0), 1.0f, 5.0f);
        const Sphere small{Vec3(0, 0, 4), 0.1f, 0};
        d.scene.shapes.of<Sphere>().insert(
            small_first ? d.scene.shapes.of<Sphere>().begin() : d.scene.shapes.of<Sphere>().end(),
            small);
        const SphereChoice c = choose(d);
        const WithinReason r = parse_within(c.reason);
        expect_relative(c.worst_float_error_px, float_error_px(5.0, 1.0), 1e-5);
        expect_relative(r.error_px, float_error_px(5.0, 1.0));
        EXPECT_EQ(r.level, 4) << small_first;
        expect_relative(r.radius_px, 1.0 / (5.0 * pixel_angle(45.0, 512)));
    }
}

TEST(SphereMethodChoice, TinySpheresFarFromTheOriginAreReportedNotDoubled) {
    // A 1 mm sphere seen from 1 cm, 1e5 units from the origin: float ulps there are ~0.008, so
    // the silhouette is off by pixels for every method; double cannot help (docs/stability.md).
    const SceneDescription d = one_sphere_scene(Vec3(1e5f, 0, 0), 1e-3f, 1e-2f);
    const SphereChoice c = choose(d);
    EXPECT_EQ(c.spheres.method, SphereMethod::User);
    EXPECT_EQ(c.math, SphereMath::Stable);           // not raised to double
    const double error = float_error_px(1e5, 1e-2);  // about 2948 px
    expect_relative(c.worst_float_error_px, error, 1e-4);
    const auto [quoted, budget] = parse_beyond(c.reason);
    expect_relative(quoted, error, 1e-4);
    EXPECT_EQ(budget, 0.5);
}

// The budget decides the branch: a unit sphere 5 units from an eye 1000 units from the origin
// has an estimated error of 4ε·1000/(5·pixel angle) = 0.0589 px.
TEST(SphereMethodChoice, TheBudgetSeparatesWithinFromBeyond) {
    SceneDescription d = one_sphere_scene(Vec3(1000, 0, 0), 1.0f, 5.0f);
    const double error = float_error_px(1000.0, 5.0);
    d.settings.max_error_px = static_cast<float>(0.9 * error);
    SphereChoice c = choose(d);
    expect_relative(parse_beyond(c.reason).first, error);
    expect_relative(parse_beyond(c.reason).second, 0.9 * error);
    d.settings.max_error_px = static_cast<float>(1.1 * error);
    c = choose(d);
    const WithinReason r = parse_within(c.reason);
    expect_relative(r.error_px, error);
    expect_relative(r.budget, 1.1 * error);
    EXPECT_EQ(c.math, SphereMath::Stable);
}

// Under auto an explicit seed or double math is kept, even where float is beyond the budget.
TEST(SphereMethodChoice, RequestedMathIsKeptUnderAuto) {
    for (const Vec3& offset : {Vec3(0), Vec3(1e5f, 0, 0)}) {
        SceneDescription d = offset == Vec3(0) ? one_sphere_scene(offset, 1.0f, 5.0f)
                                               : one_sphere_scene(offset, 1e-3f, 1e-2f);
        d.settings.sphere_math = SphereMath::Seed;
        SphereChoice c = choose(d);
        EXPECT_EQ(c.spheres.method, SphereMethod::User);
        EXPECT_EQ(c.math, SphereMath::Seed);
        EXPECT_EQ(c.reason, "user/seed: analytic, with the requested math");
        d.settings.sphere_math = SphereMath::Double;
        c = choose(d);
        EXPECT_EQ(c.spheres.method, SphereMethod::User);
        EXPECT_EQ(c.math, SphereMath::Double);
        EXPECT_EQ(c.reason, "user/double: analytic, with the requested math");
    }
}

TEST(SphereMethodChoice, NoSpheresNeedNoAnalysis) {
    SceneDescription d = one_sphere_scene(Vec3(0), 1.0f, 5.0f);
    d.scene.shapes.of<Sphere>().clear();
    d.settings.sphere_math = SphereMath::Double;
    const SphereChoice c = choose(d);
    EXPECT_EQ(c.spheres.method, SphereMethod::User);
    EXPECT_EQ(c.math, SphereMath::Double);
    EXPECT_EQ(c.reason, "no spheres");
    EXPECT_EQ(c.worst_float_error_px, 0.0f);
}

// An explicit method is kept with its parameters and math, even where auto would say "beyond".
TEST(SphereMethodChoice, ExplicitChoicesAreKept) {
    SceneDescription d = one_sphere_scene(Vec3(1e5f, 0, 0), 1e-3f, 1e-2f);
    d.settings.spheres = *parse_sphere_method("mesh:2");
    d.settings.spheres.mesh_smooth = false;
    SphereChoice c = choose(d);
    EXPECT_EQ(c.spheres.method, SphereMethod::Mesh);
    EXPECT_EQ(c.spheres.mesh_level, 2);
    EXPECT_FALSE(c.spheres.mesh_smooth);
    EXPECT_EQ(c.math, SphereMath::Stable);
    EXPECT_EQ(c.reason, "as requested");
    EXPECT_EQ(c.worst_float_error_px, 0.0f);
    d.settings.spheres = *parse_sphere_method("bruteforce");
    d.settings.sphere_math = SphereMath::Double;
    c = choose(d);
    EXPECT_EQ(c.spheres.method, SphereMethod::BruteForce);
    EXPECT_EQ(c.math, SphereMath::Double);
    EXPECT_EQ(c.reason, "as requested");
}

TEST(SphereMethodChoice, IcosphereLevelGrowsWithProjectedSize) {
    EXPECT_EQ(icosphere_level_for(1.0f, 0.5f), 0);
    int previous = 0;
    for (float radius_px : {4.0f, 16.0f, 64.0f, 256.0f, 1024.0f}) {
        const int level = icosphere_level_for(radius_px, 0.5f);
        EXPECT_GE(level, previous);
        EXPECT_LE(radius_px * kIcosphereMaxDepth[level], 0.5f);
        if (level > 0) {
            EXPECT_GT(radius_px * kIcosphereMaxDepth[level - 1], 0.5f);
        }
        previous = level;
    }
    EXPECT_GT(previous, 2);
}
}  // namespace
}  // namespace rayo
