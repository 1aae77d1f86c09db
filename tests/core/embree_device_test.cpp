// The process's one Embree device: the same device for every caller, its kernels capped at
// AVX2, and Embree's errors reported with Embree's own message through the error function set
// at creation.
#include "core/embree_device.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "core/accel.h"

namespace rayo {
namespace {

TEST(EmbreeDevice, OneDevicePerProcess) {
    EXPECT_NE(embree_device(), nullptr);
    EXPECT_EQ(embree_device(), embree_device());
}

// The device runs Embree's kernels up to AVX2 (kEmbreeDeviceConfig): 16-wide rays are AVX-512's
// alone, so the device reports them unsupported even on an AVX-512 CPU, while the 8-wide AVX
// kernels stay on wherever the CPU has them.
TEST(EmbreeDevice, KernelsStopAtAvx2) {
    EXPECT_EQ(rtcGetDeviceProperty(embree_device(), RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED), 0);
    if (__builtin_cpu_supports("avx2")) {
        EXPECT_EQ(rtcGetDeviceProperty(embree_device(), RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED),
                  1);
    }
}

TEST(EmbreeDevice, ErrorsCarryEmbreesMessage) {
    fail_on_embree_error("nothing pending");  // no error: no throw
    // An invalid geometry type: Embree refuses it with an error code and a message.
    EXPECT_EQ(rtcNewGeometry(embree_device(), static_cast<RTCGeometryType>(9999)), nullptr);
    try {
        fail_on_embree_error("a test");
        FAIL() << "the pending Embree error was not reported";
    } catch (const std::runtime_error& e) {
        // Embree 3.13.5 reports this as an unknown error with the text "invalid geometry type".
        EXPECT_EQ(std::string(e.what()),
                  "Embree error in a test: unknown error (invalid geometry type)");
    }
    fail_on_embree_error("after the report");  // Embree clears the error once read
}

TEST(EmbreeDevice, AccelsShareTheDeviceAndCountTheirOwnBytes) {
    Scene scene;
    scene.shapes.of<Sphere>().push_back({Vec3(0.0f), 1.0f, 0});
    const Accel small(scene);
    for (int i = 0; i < 1000; ++i) {
        scene.shapes.of<Sphere>().push_back({Vec3(static_cast<float>(i), 0.0f, 0.0f), 0.5f, 0});
    }
    const Accel large(scene);
    EXPECT_GT(small.embree_bytes(), 0u);
    EXPECT_GT(large.embree_bytes(), small.embree_bytes());
    // rtcGetSceneDevice adds a reference to the device: give it back.
    for (const Accel* accel : {&small, &large}) {
        RTCDevice device = rtcGetSceneDevice(accel->rtc_scene());
        EXPECT_EQ(device, embree_device());
        rtcReleaseDevice(device);
    }
}

}  // namespace
}  // namespace rayo
