// The emissive-mesh light's pick (shading/area_light.h MeshEmitter, core/cdf_guide.h): triangles
// drawn in proportion to area × luminance of their radiance, the guide table giving the binary
// search's triangle for every u, and the stratified grid's columns (core/sampling.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/cdf_guide.h"
#include "core/luminance.h"
#include "core/sampling.h"
#include "shading/area_light.h"

namespace rayo {
namespace {

// Triangle k lies in the plane y = 2 over x ∈ [2k, 2k + 1], facing −y (toward the origin's
// side), with legs of lengths a and b: area a·b/2.
struct Emitters {
    std::vector<float> weights;
    MeshEmitter emitter;

    void add(int k, float a, float b, const Vec3& radiance) {
        const Vec3 p0(2.0f * k, 2.0f, 0.0f);
        emitter.add(p0, p0 + Vec3(a, 0, 0), p0 + Vec3(0, 0, b), radiance);
        weights.push_back(0.5f * a * b * luminance(radiance));
    }
};

int triangle_of(const Vec3& point) {
    return static_cast<int>(std::floor(point.x / 2.0f));
}

TEST(MeshEmitterSampling, PicksTrianglesInProportionToAreaTimesEmission) {
    Emitters e;
    e.add(0, 1.0f, 1.0f, Vec3(1.0f));                // weight 0.5
    e.add(1, 1.0f, 0.25f, Vec3(4.0f));               // 0.5: small and bright
    e.add(2, 1.0f, 1.0f, Vec3(0.2f, 0.7f, 0.1f));    // a coloured one
    e.add(3, 0.5f, 0.5f, Vec3(10.0f, 10.0f, 0.0f));  // another
    e.add(4, 1.0f, 2.0f, Vec3(0.05f));               // large and dim
    e.emitter.finish();
    double total = 0.0;
    for (const float w : e.weights) total += w;

    const Vec3 shading_point(0.3f, -1.0f, 0.2f);
    constexpr int kSamples = 200000;
    std::mt19937 random(20261207);  // fixed seed: the test is deterministic
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<int> counts(e.weights.size(), 0);
    for (int i = 0; i < kSamples; ++i) {
        LightSample s;
        ASSERT_TRUE(
            e.emitter.sample(shading_point, glm::vec2(uniform(random), uniform(random)), s));
        const int k = triangle_of(shading_point + s.distance * s.direction);
        ASSERT_GE(k, 0);
        ASSERT_LT(k, static_cast<int>(counts.size()));
        ++counts[static_cast<size_t>(k)];
    }
    // Each count is binomial(N, p): within 5 standard deviations of N·p (a false failure about
    // once in 1.7 million per triangle), and the chi-square of all five below the 99.9999 %
    // point of chi-square with 4 degrees of freedom (33.4), so a pick by area alone (p = 0.03 for
    // the small bright triangle instead of 0.08) fails by far.
    double chi_square = 0.0;
    for (size_t k = 0; k < counts.size(); ++k) {
        const double p = e.weights[k] / total;
        const double expected = kSamples * p;
        const double sigma = std::sqrt(kSamples * p * (1.0 - p));
        EXPECT_NEAR(counts[k], expected, 5.0 * sigma) << "triangle " << k;
        chi_square += (counts[k] - expected) * (counts[k] - expected) / expected;
    }
    EXPECT_LT(chi_square, 33.4);
}

TEST(MeshEmitterSampling, TheGuideTableFindsTheBinarySearchesTriangle) {
    // Weights spanning six orders of magnitude, with runs of equal and of tiny ones, so that
    // buckets hold many triangles or none.
    std::vector<float> weights;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int i = 0; i < 3000; ++i) {
        const float w =
            i % 500 < 20 ? 1e-6f : (i % 7 == 0 ? 1.0f : std::pow(10.0f, -3.0f * uniform(random)));
        weights.push_back(w);
    }
    std::vector<float> cdf;
    for (const float w : weights) cdf.push_back((cdf.empty() ? 0.0f : cdf.back()) + w);
    CdfGuide guide;
    EXPECT_FALSE(guide.built_for(cdf));
    guide.build(cdf);
    ASSERT_TRUE(guide.built_for(cdf));
    const auto check = [&](float u) {
        const float target = u * cdf.back();
        const size_t expected =
            static_cast<size_t>(std::upper_bound(cdf.begin(), cdf.end(), target) - cdf.begin());
        EXPECT_EQ(guide.find(cdf, u, target), expected) << "u = " << u;
    };
    for (int i = 0; i < 200000; ++i) check(uniform(random));
    // The bucket borders, their neighbouring floats, and the ends.
    const float n = static_cast<float>(cdf.size());
    for (size_t k = 0; k <= cdf.size(); ++k) {
        const float u = static_cast<float>(k) / n;
        check(u);
        check(std::nextafter(u, 0.0f));
        check(std::nextafter(u, 1.0f));
    }
    check(0.0f);
    check(1.0f);
    check(0.99999994f);
}

TEST(MeshEmitterSampling, SamplesTheSamePointsWithAndWithoutTheGuide) {
    Emitters with, without;
    std::mt19937 random(11);
    std::uniform_real_distribution<float> uniform(0.1f, 1.0f);
    for (int k = 0; k < 257; ++k) {
        const float a = uniform(random), b = uniform(random);
        const Vec3 radiance(uniform(random), uniform(random), uniform(random));
        with.add(k, a, b, radiance);
        without.add(k, a, b, radiance);
    }
    with.emitter.finish();
    const Vec3 point(100.0f, -3.0f, 0.5f);
    for (int i = 0; i < 20000; ++i) {
        const glm::vec2 u(uniform(random) - 0.1f, uniform(random) - 0.1f);
        LightSample a, b;
        ASSERT_TRUE(with.emitter.sample(point, u, a));
        ASSERT_TRUE(without.emitter.sample(point, u, b));
        EXPECT_EQ(a.direction, b.direction);
        EXPECT_EQ(a.distance, b.distance);
        EXPECT_EQ(a.pdf, b.pdf);
        EXPECT_EQ(a.radiance, b.radiance);
    }
}

TEST(MeshEmitterSampling, AnAddAfterFinishStillSamplesEveryTriangle) {
    Emitters e;
    e.add(0, 1.0f, 1.0f, Vec3(1.0f));
    e.emitter.finish();
    e.add(1, 1.0f, 1.0f, Vec3(1.0f));  // the guide is stale: the search covers both
    LightSample s;
    ASSERT_TRUE(e.emitter.sample(Vec3(0.0f), glm::vec2(0.9f, 0.5f), s));
    EXPECT_EQ(triangle_of(s.distance * s.direction), 1);
}

// The columns of the stratified grid: the largest divisor of spp not above √spp (the old loop
// over every candidate, kept here as the reference).
TEST(StratifiedOffset, ColumnsAreTheLargestDivisorNotAboveTheSquareRoot) {
    for (uint32_t spp = 2; spp <= 5000; ++spp) {
        uint32_t columns = 1;
        for (uint32_t c = 1; c * c <= spp; ++c) {
            if (spp % c == 0) columns = c;
        }
        const uint32_t rows = spp / columns;
        // Sample s sits in column s % columns, row s / columns: its offset lies in that cell.
        for (const uint32_t s : {0u, spp / 2, spp - 1}) {
            const PixelOffset o = stratified_offset(3, 4, s, spp);
            const float x = (o.dx + 0.5f) * columns, y = (o.dy + 0.5f) * rows;
            EXPECT_NEAR(x, (s % columns) + 0.5f, 0.5f + 1e-3f) << spp << " " << s;
            EXPECT_NEAR(y, (s / columns) + 0.5f, 0.5f + 1e-3f) << spp << " " << s;
        }
    }
}

}  // namespace
}  // namespace rayo
