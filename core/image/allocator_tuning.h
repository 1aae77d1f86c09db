#pragma once
// glibc malloc settings for writing images. OpenEXR compresses every tile (or block of scanlines)
// on its thread pool and frees its buffers afterwards; by default glibc then gives the top of each
// thread's arena back to the kernel (madvise), and the next tile faults the same pages in again.
// On this machine that churn cost more than the zip compression itself: a 2048² float EXR took
// 3.8 s to write by default and 0.9 s with the settings below (docs/performance.md "EXR output").

namespace rayo {

// Keeps up to 16 MB of freed memory at the top of each arena instead of returning it at once
// (M_TRIM_THRESHOLD), and serves blocks under 4 MB from the arenas rather than fresh mappings
// (M_MMAP_THRESHOLD: setting the trim threshold fixes it, which would otherwise stay at 128 KB).
// Process-wide; call once at start. Neither setting changes what is computed.
void tune_allocator_for_image_writing();

}  // namespace rayo
