// The main of every test binary: the product's floating-point mode (core/float_mode.h), then
// GoogleTest. Without it the tests would check bits the product never computes.
#include <gtest/gtest.h>

#include "core/float_mode.h"

int main(int argc, char** argv) {
    rayo::set_flush_denormals_to_zero();
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
