#pragma once
// The assertions several test binaries share: a 3-vector near expected components, and film
// (image) comparisons: one version here instead of a copy per test file (docs/architecture.md).
#include <gtest/gtest.h>

#include <cstring>
#include <glm/vec3.hpp>

#include "core/film.h"

namespace rayo_test {

// EXPECT_NEAR on each component of `actual` against (x, y, z); a tolerance of 0 asks for exact
// equality. The default, 1e-6, is a few float ulps of unit-sized values: what the loader tests
// allow for values the loaders compute (0.1 × colour, normalized vectors). For float and double
// vectors alike (the sphere tests run both).
template <typename T>
void expect_vec3(const glm::vec<3, T>& actual, double x, double y, double z,
                 double tolerance = 1e-6) {
    ::testing::Message vector;
    vector << "in (" << actual.x << ", " << actual.y << ", " << actual.z << ")";
    EXPECT_NEAR(actual.x, x, tolerance) << vector;
    EXPECT_NEAR(actual.y, y, tolerance) << vector;
    EXPECT_NEAR(actual.z, z, tolerance) << vector;
}

// The same against an expected vector.
template <typename T>
void expect_vec_near(const glm::vec<3, T>& actual, const glm::vec<3, T>& expected,
                     double tolerance) {
    expect_vec3(actual, expected.x, expected.y, expected.z, tolerance);
}

// How many pixels of two films of the same size differ in any RGB channel (bit for bit: any
// difference counts).
inline int differing_pixels(const rayo::Film& a, const rayo::Film& b) {
    EXPECT_EQ(a.width(), b.width());
    EXPECT_EQ(a.height(), b.height());
    if (a.width() != b.width() || a.height() != b.height()) return a.width() * a.height();
    int n = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) n += a.rgb(x, y) != b.rgb(x, y);
    }
    return n;
}

// Whether two films have the same size and the same bits in every RGBA float (memcmp: a NaN
// compares equal to the same NaN, and -0 differs from +0).
inline bool same_bits(const rayo::Film& a, const rayo::Film& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           a.rgba().size() == b.rgba().size() &&
           std::memcmp(a.rgba().data(), b.rgba().data(), a.rgba().size() * sizeof(float)) == 0;
}

}  // namespace rayo_test
