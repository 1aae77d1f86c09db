#pragma once
// The floating-point mode rayo runs in: flush-to-zero and denormals-are-zero, as Embree
// recommends (docs/architecture.md, "Hot-path rules"). Set once per thread that traces rays,
// by main() in the product and by the test main in the tests, so both compute the same bits.
#include <pmmintrin.h>
#include <xmmintrin.h>

namespace rayo {

inline void set_flush_denormals_to_zero() {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
}

}  // namespace rayo
