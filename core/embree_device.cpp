#include "core/embree_device.h"

#include <atomic>
#include <mutex>
#include <stdexcept>

namespace rayo {
namespace {

std::atomic<long long> g_bytes{0};
std::mutex g_message_mutex;
std::string g_last_message;  // the error function's last message, read by fail_on_embree_error

const char* error_name(RTCError error) {
    switch (error) {
        case RTC_ERROR_NONE:
            return "none";
        case RTC_ERROR_UNKNOWN:
            return "unknown error";
        case RTC_ERROR_INVALID_ARGUMENT:
            return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION:
            return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY:
            return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU:
            return "unsupported CPU";
        case RTC_ERROR_CANCELLED:
            return "cancelled";
    }
    return "unknown error";
}

struct Device {
    RTCDevice device = nullptr;
    Device() {
        device = rtcNewDevice(kEmbreeDeviceConfig);
        if (!device) {
            throw std::runtime_error(std::string("Embree: cannot create a device: ") +
                                     error_name(rtcGetDeviceError(nullptr)));
        }
        rtcSetDeviceErrorFunction(
            device,
            [](void*, RTCError, const char* message) {
                const std::lock_guard<std::mutex> lock(g_message_mutex);
                g_last_message = message ? message : "";
            },
            nullptr);
        rtcSetDeviceMemoryMonitorFunction(
            device,
            [](void*, ssize_t bytes, bool /*post*/) {
                g_bytes.fetch_add(bytes);
                return true;  // never refuse an allocation
            },
            nullptr);
    }
    ~Device() { rtcReleaseDevice(device); }
};

}  // namespace

RTCDevice embree_device() {
    static Device device;  // thread-safe initialization (C++11 magic statics)
    return device.device;
}

void fail_on_embree_error(const char* what) {
    const RTCError error = rtcGetDeviceError(embree_device());
    if (error == RTC_ERROR_NONE) return;
    std::string message;
    {
        const std::lock_guard<std::mutex> lock(g_message_mutex);
        message = g_last_message;
    }
    throw std::runtime_error(std::string("Embree error in ") + what + ": " + error_name(error) +
                             (message.empty() ? "" : " (" + message + ")"));
}

long long embree_bytes_in_use() {
    return g_bytes.load();
}

int embree_native_packet_width() {
    const RTCDevice device = embree_device();
    if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)) return 16;
    if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)) return 8;
    if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED)) return 4;
    return 1;
}

}  // namespace rayo
