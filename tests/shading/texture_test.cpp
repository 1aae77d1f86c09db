// Solid textures (seed 003 ch. 3): colour ramps, every named kind in range and deterministic, the
// pool-bottom preset within its water ramp, and bump mapping.
#include "shading/texture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.h"

namespace rayo {
namespace {

Vec3 point(int i, float extent) {
    const uint32_t h = hash_u32(static_cast<uint32_t>(i) * 104729u + 3u);
    return Vec3((unit_float(h) - 0.5f) * 2 * extent,
                (unit_float(hash_u32(h + 1)) - 0.5f) * 2 * extent,
                (unit_float(hash_u32(h + 2)) - 0.5f) * 2 * extent);
}

TEST(TextureRamp, InterpolatesBetweenAnyNumberOfSortedStops) {
    const ColorRamp ramp({{1.0f, Vec3(0, 0, 1)}, {0.0f, Vec3(1, 0, 0)}, {0.5f, Vec3(0, 1, 0)}});
    ASSERT_EQ(ramp.stops().size(), 3u);
    EXPECT_EQ(ramp.stops()[1].position, 0.5f);  // sorted
    EXPECT_EQ(ramp.eval(0.0f), Vec3(1, 0, 0));
    EXPECT_EQ(ramp.eval(0.5f), Vec3(0, 1, 0));
    EXPECT_EQ(ramp.eval(1.0f), Vec3(0, 0, 1));
    const Vec3 quarter = ramp.eval(0.25f);
    EXPECT_FLOAT_EQ(quarter.x, 0.5f);
    EXPECT_FLOAT_EQ(quarter.y, 0.5f);
    EXPECT_FLOAT_EQ(quarter.z, 0.0f);
    EXPECT_EQ(ramp.eval(-3.0f), Vec3(1, 0, 0));  // beyond the ends: the end colours
    EXPECT_EQ(ramp.eval(7.0f), Vec3(0, 0, 1));
    EXPECT_EQ(ramp.eval(std::nanf("")), Vec3(1, 0, 0));
    const ColorRamp single({{0.3f, Vec3(0.2f)}});
    EXPECT_EQ(single.eval(0.9f), Vec3(0.2f));
    EXPECT_THROW(ColorRamp(std::vector<ColorStop>{}), std::invalid_argument);
    // A hard step: two stops at the same position.
    const ColorRamp step({{0.5f, Vec3(0.0f)}, {0.5f, Vec3(1.0f)}});
    EXPECT_EQ(step.eval(0.49f), Vec3(0.0f));
    EXPECT_EQ(step.eval(0.51f), Vec3(1.0f));
}

TEST(TextureRamp, SrgbDecoding) {
    EXPECT_EQ(srgb8_to_linear(0), 0.0f);
    EXPECT_FLOAT_EQ(srgb8_to_linear(255), 1.0f);
    EXPECT_NEAR(srgb8_to_linear(128), 0.2158605f, 1e-6f);
    EXPECT_NEAR(srgb8_to_linear(10), 10.0f / 255.0f / 12.92f, 1e-7f);
}

TEST(TextureKinds, EveryKindIsFiniteInRangeAndInsideItsRamp) {
    for (const std::string& kind : texture_kind_names()) {
        Texture t = make_texture(kind);
        t.scale = 0.7f;
        Vec3 lo(1e9f), hi(-1e9f);
        for (const ColorStop& s : t.ramp.stops()) {
            lo = glm::min(lo, s.color);
            hi = glm::max(hi, s.color);
        }
        float vmin = 1e9f, vmax = -1e9f;
        for (int i = 0; i < 3000; ++i) {
            const Vec3 p = point(i, 300.0f);
            const float v = t.value(p);
            ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << kind << " " << v;
            vmin = std::min(vmin, v);
            vmax = std::max(vmax, v);
            const Vec3 c = t.color(p);
            if (kind == "constant") {
                ASSERT_EQ(c, std::get<ConstantMap>(t.map).color);
                continue;
            }
            for (int k = 0; k < 3; ++k) {
                ASSERT_GE(c[k], lo[k] - 1e-6f) << kind;
                ASSERT_LE(c[k], hi[k] + 1e-6f) << kind;
            }
        }
        if (kind != "constant") {
            EXPECT_GT(vmax - vmin, 0.3f) << kind << " barely varies";
        }
    }
    EXPECT_THROW(make_texture("plaid"), InputError);
}

TEST(TextureKinds, PoolBottomUsesTheSeedsWaterRampAndStaysInIt) {
    const Texture t = make_texture("pool-bottom");
    ASSERT_EQ(t.ramp.stops().size(), 2u);
    const Vec3 dark = srgb8_to_linear(40, 100, 162), light = srgb8_to_linear(91, 187, 201);
    EXPECT_EQ(t.ramp.stops().front().color, dark);
    EXPECT_EQ(t.ramp.stops().back().color, light);
    double sum = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const Vec3 p = point(i, 40.0f);
        const Vec3 c = t.color(p);
        for (int k = 0; k < 3; ++k) {
            ASSERT_GE(c[k], dark[k] - 1e-6f);
            ASSERT_LE(c[k], light[k] + 1e-6f);
        }
        sum += t.value(p);
    }
    // Squared maps in [0, 1] mixed 0.3/0.7: mostly dark water with bright cell edges.
    EXPECT_GT(sum / n, 0.1);
    EXPECT_LT(sum / n, 0.6);
}

TEST(TextureKinds, ScaleAndSeed) {
    Texture a = make_texture("perlin");
    Texture b = a;
    b.scale = 2.0f;
    for (int i = 0; i < 200; ++i) {
        const Vec3 p = point(i, 10.0f);
        EXPECT_EQ(a.value(p), b.value(2.0f * p));
    }
    Texture c = a;
    c.seed = 99;
    int differ = 0;
    for (int i = 0; i < 200; ++i) differ += a.value(point(i, 10.0f)) != c.value(point(i, 10.0f));
    EXPECT_GE(differ, 195);
}

// Every kind gives the same bits for the same (point, seed) on every call, whatever was
// evaluated in between (no hidden state), and every kind but the constant one depends on its
// seed (the scenes' "seed" field must change the pattern, not only for perlin).
TEST(TextureKinds, EveryKindRepeatsForASeedAndChangesWithIt) {
    for (const std::string& kind : texture_kind_names()) {
        Texture t = make_texture(kind);
        t.seed = 5;
        Texture other = t;
        other.seed = 6;
        const int n = 500;
        std::vector<Vec3> first(n);
        std::vector<float> first_value(n);
        for (int i = 0; i < n; ++i) {
            first[i] = t.color(point(i, 20.0f));
            first_value[i] = t.value(point(i, 20.0f));
        }
        int differ = 0;
        for (int i = n - 1; i >= 0; --i) {  // again, in reverse order, after the other seed
            differ += other.value(point(i, 20.0f)) != first_value[i];
            ASSERT_EQ(t.color(point(i, 20.0f)), first[i]) << kind << " " << i;
            ASSERT_EQ(t.value(point(i, 20.0f)), first_value[i]) << kind << " " << i;
        }
        if (kind == "constant") {
            EXPECT_EQ(differ, 0);
        } else {
            EXPECT_GE(differ, n * 95 / 100) << kind;
        }
    }
}

// Marble without distortion is 0.5 + 0.5·sin(2π·f·x/scale): its gradient is known.
TEST(TextureBump, GradientMatchesTheAnalyticDerivative) {
    Texture t = make_texture("marble");
    auto& m = std::get<MarbleMap>(t.map);
    m.distortion = 0.0f;
    m.frequency = 0.5f;
    t.scale = 2.0f;
    for (float x = -3.0f; x < 3.0f; x += 0.37f) {
        const Vec3 g = t.gradient(Vec3(x, 0.2f, -1.1f));
        const float k = 2.0f * kPi * m.frequency / t.scale;
        EXPECT_NEAR(g.x, 0.5f * k * std::cos(k * x), 2e-3f) << x;
        EXPECT_NEAR(g.y, 0.0f, 1e-6f);
        EXPECT_NEAR(g.z, 0.0f, 1e-6f);
    }
    EXPECT_EQ(make_texture("constant").gradient(Vec3(1.0f)), Vec3(0.0f));
}

TEST(TextureBump, PerturbsOnlyByTheTangentialGradient) {
    const Vec3 n(0, 0, 1);
    EXPECT_EQ(perturb_normal(n, Vec3(0.0f), 5.0f, n), n);        // flat texture
    EXPECT_EQ(perturb_normal(n, Vec3(0, 0, 3.0f), 5.0f, n), n);  // varies only along n
    EXPECT_EQ(perturb_normal(n, Vec3(1, 0, 0), 0.0f, n), n);     // no strength
    const Vec3 tilted = perturb_normal(n, Vec3(1, 0, 0), 1.0f, n);
    EXPECT_NEAR(glm::length(tilted), 1.0f, 1e-6f);
    EXPECT_NEAR(tilted.x, -std::sqrt(0.5f), 1e-6f);  // normalize(n − ∇): leans away from uphill
    EXPECT_NEAR(tilted.z, std::sqrt(0.5f), 1e-6f);
    // However strong the bump, the normal stays on the geometric normal's side.
    const Vec3 steep = perturb_normal(n, Vec3(1, 0, 0), 1e6f, n);
    EXPECT_GT(glm::dot(steep, n), 0.0f);
    EXPECT_NEAR(glm::length(steep), 1.0f, 1e-5f);
    const Vec3 not_finite = perturb_normal(n, Vec3(INFINITY, 0, 0), 1.0f, n);
    EXPECT_EQ(not_finite, n);
}

TEST(TextureBump, ChangesTheNormalOnlyWhereTheTextureVaries) {
    Texture stripes = make_texture("marble");  // varies along x only
    std::get<MarbleMap>(stripes.map).distortion = 0.0f;
    const Texture flat = make_texture("constant");
    int changed_across = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec3 p = point(i, 5.0f);
        // A surface facing x: the texture is constant along it, so the normal must not move.
        const Vec3 nx(1, 0, 0);
        const Vec3 bx = bump_normal(stripes, 1.0f, p, nx, nx);
        EXPECT_NEAR(bx.x, 1.0f, 1e-6f);
        EXPECT_NEAR(bx.y, 0.0f, 1e-4f);
        EXPECT_NEAR(bx.z, 0.0f, 1e-4f);
        // A surface facing y sees the stripes vary across it.
        const Vec3 ny(0, 1, 0);
        changed_across += glm::dot(bump_normal(stripes, 1.0f, p, ny, ny), ny) < 0.999f;
        EXPECT_EQ(bump_normal(flat, 1.0f, p, ny, ny), ny);
    }
    EXPECT_GT(changed_across, 150);
}
}  // namespace
}  // namespace rayo
