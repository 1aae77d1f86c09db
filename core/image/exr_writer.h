#pragma once
// OpenEXR files written with the OpenEXR library directly (docs/performance.md "Writing PNG and
// EXR without OpenImageIO"): the ImageWriter of core/image_library.h for .exr, so that a render
// writing EXR never loads the image module. Writes what OpenImageIO's OpenEXR writer writes for
// rayo's spec: channels R, G, B(, A) of half or float, scanlines (tile_size 0) or tiles of
// tile_size (one level), the "compression" attribute by OpenImageIO's names (none, rle, zips, zip,
// piz, pxr24, b44, b44a, dwaa, dwab), "chromaticities", the line order of "openexr:lineOrder"
// (increasingY, decreasingY, randomY), capDate (the time of writing, as OpenImageIO adds it), and
// every other attribute as a string, int or float (vector) attribute of the same name. Compression
// runs on OpenEXR's thread pool, one thread per core, as OpenImageIO sets it.
#include <memory>
#include <string>

#include "core/image_library.h"

namespace rayo {

// Creates `path` and writes its header; null with the reason in `error` (errno kept from the
// failing call) when the file cannot be created or the spec is not an EXR's.
std::unique_ptr<ImageWriter> create_exr_writer(const std::string& path, const ImageFileSpec& spec,
                                               std::string& error);

}  // namespace rayo
