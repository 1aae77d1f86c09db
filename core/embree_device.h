#pragma once
// The process's one Embree device (Embree's tutorials: one device per application), created on
// first use with its error function set right after rtcNewDevice, so every Embree error is
// reported with Embree's own message.
#include <embree3/rtcore.h>

#include <string>

namespace rayo {

// The device's configuration. Embree's kernels stop at AVX2: Debian's Embree 3.13.5 AVX-512
// stream/packet traversal (16-wide, chosen on AVX-512 CPUs) can spin forever inside
// rtcOccluded1M on an instanced scene, depending on what the process traced before (reproduced:
// a CSG or instance render, then a glTF scene with instanced meshes, in one process; the same
// rays with rtcOccluded1 or with the AVX2 kernels finish). Measured on this AMD EPYC (Zen 4):
// AVX2 within run-to-run noise of AVX-512 on balls_3 and teapot_3 at 2048² (docs/performance.md).
inline constexpr const char* kEmbreeDeviceConfig = "max_isa=avx2";

RTCDevice embree_device();

// Throws std::runtime_error naming `what`, Embree's error code and message, when the device
// has an error pending.
void fail_on_embree_error(const char* what);

// Bytes Embree holds for all scenes alive in the process (its memory monitor).
long long embree_bytes_in_use();

// The widest ray packet the device's kernels take natively, as rtcGetDeviceProperty reports it
// under kEmbreeDeviceConfig's cap: 16 (AVX-512), 8 (AVX or AVX2), 4 (SSE), or 1. Embree 3 has no
// call that names the ISA it chose; this is its vector width.
int embree_native_packet_width();

}  // namespace rayo
