// Tests of Cohen–Sutherland clipping (core/line_clipping.h): the seed 003 region codes
// (fig. 1.8) and the clipped end points of hand-computed lines like those of fig. 1.9.
#include "core/line_clipping.h"

#include <gtest/gtest.h>

#include <limits>

namespace rayo {
namespace {

const ClipRect kRect{0.0, 0.0, 10.0, 10.0};

TEST(RegionCode, NineZonesAsTheSeedWritesThem) {
    EXPECT_EQ(region_code(kRect, DVec2(5, 5)), 0b0000);
    EXPECT_EQ(region_code(kRect, DVec2(-1, 5)), 0b1000);  // x < x_min
    EXPECT_EQ(region_code(kRect, DVec2(11, 5)), 0b0100);  // x > x_max
    EXPECT_EQ(region_code(kRect, DVec2(5, -1)), 0b0010);  // y < y_min
    EXPECT_EQ(region_code(kRect, DVec2(5, 11)), 0b0001);  // y > y_max
    EXPECT_EQ(region_code(kRect, DVec2(-1, -1)), 0b1010);
    EXPECT_EQ(region_code(kRect, DVec2(-1, 11)), 0b1001);
    EXPECT_EQ(region_code(kRect, DVec2(11, -1)), 0b0110);
    EXPECT_EQ(region_code(kRect, DVec2(11, 11)), 0b0101);
}

TEST(RegionCode, BordersAreInside) {
    // seed 003 §1.3: x_min <= x <= x_max and y_min <= y <= y_max.
    EXPECT_EQ(region_code(kRect, DVec2(0, 0)), 0);
    EXPECT_EQ(region_code(kRect, DVec2(10, 10)), 0);
    EXPECT_EQ(region_code(kRect, DVec2(0, 10)), 0);
    EXPECT_EQ(region_code(kRect, DVec2(-1e-12, 3)), 0b1000);
}

TEST(ClipSegment, BothInsideIsKeptWhole) {  // fig. 1.9's C–D
    DVec2 c(1, 2), d(9, 8);
    ASSERT_TRUE(clip_segment(kRect, c, d));
    EXPECT_EQ(c, DVec2(1, 2));
    EXPECT_EQ(d, DVec2(9, 8));
}

TEST(ClipSegment, CodesSharingABitAreDiscarded) {  // fig. 1.9's G (0100) – H (0110)
    DVec2 g(12, 5), h(12, -3);
    EXPECT_EQ(region_code(kRect, g), 0b0100);
    EXPECT_EQ(region_code(kRect, h), 0b0110);
    EXPECT_FALSE(clip_segment(kRect, g, h));
}

TEST(ClipSegment, BothEndsOutsideAreMovedToTheirBorders) {
    // fig. 1.9's A (1000) – B (0001): A' on x = x_min, B' on y = y_max. The line
    // (−2, 4) + t(6, 8): x = 0 at t0 = 1/3, y = 4 + 8/3 (eqs. 1.1, 1.2); y = 10 at
    // t1 = 3/4, x = −2 + 4.5 = 2.5.
    DVec2 a(-2, 4), b(4, 12);
    EXPECT_EQ(region_code(kRect, a), 0b1000);
    EXPECT_EQ(region_code(kRect, b), 0b0001);
    ASSERT_TRUE(clip_segment(kRect, a, b));
    EXPECT_DOUBLE_EQ(a.x, 0.0);
    EXPECT_DOUBLE_EQ(a.y, 4.0 + 8.0 / 3.0);
    EXPECT_DOUBLE_EQ(b.x, 2.5);
    EXPECT_DOUBLE_EQ(b.y, 10.0);
}

TEST(ClipSegment, OneEndOutsideIsMovedOnly) {  // fig. 1.9's E–F: one crossing, E'
    DVec2 e(5, 5), f(15, 7.5);
    ASSERT_TRUE(clip_segment(kRect, e, f));
    EXPECT_EQ(e, DVec2(5, 5));
    EXPECT_DOUBLE_EQ(f.x, 10.0);
    EXPECT_DOUBLE_EQ(f.y, 6.25);  // t = 1/2
}

TEST(ClipSegment, OutsideEndFirstInTheSegmentsOrder) {
    DVec2 a(5, -5), b(5, 5);  // a below y_min: a' = (5, 0)
    ASSERT_TRUE(clip_segment(kRect, a, b));
    EXPECT_EQ(a, DVec2(5, 0));
    EXPECT_EQ(b, DVec2(5, 5));
}

TEST(ClipSegment, CrossingTwoBordersAtOneEnd) {
    // (−5, 5) to (5, 15): an end beyond x_min and one beyond y_max; the line y = x + 10 touches
    // the rectangle only at its corner (0, 10).
    DVec2 a(-5, 5), b(5, 15);
    ASSERT_TRUE(clip_segment(kRect, a, b));
    EXPECT_DOUBLE_EQ(a.x, 0.0);
    EXPECT_DOUBLE_EQ(a.y, 10.0);
    EXPECT_DOUBLE_EQ(b.x, 0.0);
    EXPECT_DOUBLE_EQ(b.y, 10.0);
}

TEST(ClipSegment, CodesWithoutCommonBitThatMissAreDiscarded) {
    // (−2, 9) 1000 and (1, 12) 0001: AND = 0000, yet the line y = x + 11 passes above the
    // corner (0, 10): after moving the ends both lie beyond y_max.
    DVec2 a(-2, 9), b(1, 12);
    EXPECT_EQ(region_code(kRect, a) & region_code(kRect, b), 0);
    EXPECT_FALSE(clip_segment(kRect, a, b));
}

TEST(ClipSegment, DiagonalThroughTheWholeRectangle) {
    DVec2 a(-5, -5), b(20, 20);
    ASSERT_TRUE(clip_segment(kRect, a, b));
    EXPECT_EQ(a, DVec2(0, 0));
    EXPECT_EQ(b, DVec2(10, 10));
}

TEST(ClipSegment, NonFiniteEndsAreDiscarded) {
    DVec2 a(5, 5), b(std::numeric_limits<double>::infinity(), 5);
    EXPECT_FALSE(clip_segment(kRect, a, b));
    DVec2 c(std::numeric_limits<double>::quiet_NaN(), 5), d(5, 5);
    EXPECT_FALSE(clip_segment(kRect, c, d));
}

}  // namespace
}  // namespace rayo
