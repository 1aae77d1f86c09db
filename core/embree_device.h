#pragma once
// The process's one Embree device (Embree's tutorials: one device per application), created on
// first use with its error function set right after rtcNewDevice, so every Embree error is
// reported with Embree's own message.
#include <embree3/rtcore.h>

#include <string>

namespace rayo {

RTCDevice embree_device();

// Throws std::runtime_error naming `what`, Embree's error code and message, when the device
// has an error pending.
void fail_on_embree_error(const char* what);

// Bytes Embree holds for all scenes alive in the process (its memory monitor).
long long embree_bytes_in_use();

}  // namespace rayo
