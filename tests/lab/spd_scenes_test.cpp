// The SPD generators (bench/lab/spd_scenes.h) against the object counts of the Standard
// Procedural Databases, computed here from the published formulas (never from the SPD's files).
#include "bench/lab/spd_scenes.h"

#include <gtest/gtest.h>

#include "bench/lab/spd_povray.h"
#include "core/error.h"

namespace rayo {
namespace {

struct Counts {
    size_t spheres = 0, cones = 0, triangles = 0, lights = 0;
};

size_t power(size_t base, int exponent) {
    size_t p = 1;
    for (int i = 0; i < exponent; ++i) p *= base;
    return p;
}

// The SPD's counts at size n (its README and Haines 1987), floors and walls included.
Counts expected(const std::string& name, int n) {
    Counts c;
    if (name == "balls") {  // sphereflake: Σ_{i=0..n} 9^i spheres; a floor square
        for (int i = 0; i <= n; ++i) c.spheres += power(9, i);
        c.triangles = 2;
        c.lights = 3;
    } else if (name == "gears") {  // n³ gears: two 144-gons (142 triangles) and 144 quads each
        c.triangles = power(n, 3) * (2 * 142 + 144 * 2) + 2;
        c.lights = 5;
    } else if (name == "mount") {  // 2^n × 2^n cells of two triangles; four glass spheres
        c.triangles = 2 * power(4, n);
        c.spheres = 4;
        c.lights = 1;
    } else if (name == "rings") {  // 6·Σ i² rings of 5 cylinders and 5 spheres; a wall
        size_t rings = 0;
        for (int i = 1; i <= n; ++i) rings += 6 * size_t(i) * i;
        c.spheres = c.cones = 5 * rings;
        c.triangles = 2;
        c.lights = 3;
    } else if (name == "teapot") {  // 32 patches × n² quads, 8n lost at the poles; n² floor squares
        c.triangles = 64 * size_t(n) * n - 8 * size_t(n) + 2 * size_t(n) * n;
        c.lights = 2;
    } else if (name == "tetra") {  // 4^(n−1) tetrahedra of 4 faces
        c.triangles = power(4, n);
        c.lights = 1;
    } else if (name == "tree") {  // 2^(n+1) − 1 branches: a cone and a sphere each; a floor
        c.spheres = c.cones = power(2, n + 1) - 1;
        c.triangles = 2;
        c.lights = 7;
    }
    return c;
}

TEST(SpdScenes, CountsMatchThePublishedFormulas) {
    ASSERT_EQ(spd_scene_names().size(), 7u);
    for (const std::string& name : spd_scene_names()) {
        for (int n = 1; n <= 3; ++n) {
            if (n > spd_max_size(name)) continue;
            const SceneDescription d = spd_scene(name, n);
            const Counts want = expected(name, n);
            SCOPED_TRACE(name + " " + std::to_string(n));
            EXPECT_EQ(d.source, "spd:" + name + ":" + std::to_string(n));
            EXPECT_EQ(d.scene.shapes.of<Sphere>().size(), want.spheres);
            EXPECT_EQ(d.scene.shapes.of<Cone>().size(), want.cones);
            EXPECT_EQ(d.scene.triangle_count() + d.skipped_triangles, want.triangles);
            EXPECT_EQ(d.shading.lights.size(), want.lights);
        }
    }
}

TEST(SpdScenes, TheSphereflakeChildrenTouchTheirParent) {
    // Nine children of a third of the radius on the surface of each sphere (Haines 1987).
    const SceneDescription d = spd_scene("balls", 2);
    const auto& s = d.scene.shapes.of<Sphere>();
    ASSERT_EQ(s.size(), 91u);
    for (size_t child = 1; child <= 81; child += 10) {  // pre-order: each child, then its own
        EXPECT_NEAR(glm::length(s[child].center - s[0].center), s[0].radius * 4 / 3, 1e-5);
        EXPECT_NEAR(s[child].radius, s[0].radius / 3, 1e-6);
    }
}

TEST(SpdScenes, GearsAndMountAreTheSpds) {
    // The SPD's own files (its generators, version 3.14) print these lines: gears 2's first
    // gear is glass (Ks 0, T 0.8) in the colour of its grid place, its second opaque white;
    // mount 3's first triangle has the heights of the SPD's hash and Gaussian numbers.
    const std::string gears = spd_nff("gears", 2);
    EXPECT_NE(gears.find("f 1 0.605523 0.408284 0.2 0 100000 0.8 1.1\n"), std::string::npos);
    EXPECT_NE(gears.find("f 0.802761 1 1 0.2 0 100000 0.8 1.1\n"), std::string::npos);
    EXPECT_NE(gears.find("f 1 1 1 1 0 100000 0 0\n"), std::string::npos);
    const std::string mount = spd_nff("mount", 3);
    EXPECT_NE(mount.find("p 3\n-1 -1 0\n-0.75 -1 -0.296434\n-0.75 -0.75 -0.0309146\n"),
              std::string::npos);
    EXPECT_NE(mount.find("p 3\n-0.75 -1 -0.296434\n-0.5 -1 -0.466589\n-0.5 -0.75 -0.0307771\n"),
              std::string::npos);
}

TEST(SpdScenes, BadNamesAndSizesAreInputErrors) {
    EXPECT_THROW(spd_nff("bunny", 1), InputError);
    EXPECT_THROW(spd_nff("balls", 0), InputError);
    EXPECT_THROW(spd_nff("balls", spd_max_size("balls") + 1), InputError);
    try {
        spd_nff("tetra", 99);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("spd:tetra"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("1..9"), std::string::npos) << e.what();
    }
}

TEST(SpdPovray, TranslatesEveryKindOfLine) {
    const std::string pov = nff_to_povray(spd_nff("rings", 1), 256);
    EXPECT_NE(pov.find("#version 3.7;"), std::string::npos);
    EXPECT_NE(pov.find("light_source { <3, -2.61313, 3> color rgb 0.57735"), std::string::npos);
    EXPECT_NE(pov.find("cone { <0.930995, 2.61313, 0>, 0.07412, <0.287693, 1.7277, 0>, 0.07412 "
                       "open"),
              std::string::npos);
    EXPECT_NE(nff_to_povray(spd_nff("teapot", 1), 256).find("smooth_triangle { <1.4, 0, 2.4> <"),
              std::string::npos);
    EXPECT_NE(pov.find("polygon { 5, <"), std::string::npos);
    // A filtering surface: ambient and diffuse raised by 1/(1 − T).
    const std::string glass = nff_to_povray(spd_nff("mount", 1), 64);
    EXPECT_NE(glass.find("filter 0.9 }\n  finish { ambient 1 diffuse 1 phong 0.1"),
              std::string::npos)
        << glass.substr(0, 800);
    EXPECT_THROW(nff_to_povray("x 1 2 3\n", 64), InputError);
}

}  // namespace
}  // namespace rayo
