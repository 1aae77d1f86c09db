// Rec. 709 luminance (core/luminance.h): its weights, and white at 1.
#include "core/luminance.h"

#include <gtest/gtest.h>

namespace rayo {
namespace {

TEST(Luminance, Rec709WeightsSumToOne) {
    EXPECT_FLOAT_EQ(luminance(1.0f, 0.0f, 0.0f), 0.2126f);
    EXPECT_FLOAT_EQ(luminance(0.0f, 1.0f, 0.0f), 0.7152f);
    EXPECT_FLOAT_EQ(luminance(0.0f, 0.0f, 1.0f), 0.0722f);
    EXPECT_FLOAT_EQ(luminance(Vec3(1.0f)), 1.0f);
    EXPECT_FLOAT_EQ(luminance(Vec3(0.5f, 0.25f, 2.0f)), luminance(0.5f, 0.25f, 2.0f));
}

}  // namespace
}  // namespace rayo
