#pragma once
// PNG files written with libpng directly (docs/performance.md "Writing PNG and EXR without
// OpenImageIO"): the ImageWriter of core/image_library.h for .png, so that a render writing PNG
// never loads the image module. Writes what OpenImageIO's PNG writer writes for rayo's spec:
// 8- or 16-bit grey, grey + alpha, RGB or RGBA (alpha unassociated), an oFFs chunk of (0, 0),
// every text attribute as a tEXt chunk, the zlib level of "png:compressionLevel" and the row
// filter of "png:filter" (libpng's PNG_FILTER_* bits). Rows are written in order (write_image,
// or write_scanlines from the top down); tiles are not (PNG has none).
#include <memory>
#include <string>

#include "core/image_library.h"

namespace rayo {

// Creates `path` and writes the header and text chunks; null with the reason in `error` (errno
// kept from the failing call) when the file cannot be created or the spec is not a PNG's.
std::unique_ptr<ImageWriter> create_png_writer(const std::string& path, const ImageFileSpec& spec,
                                               std::string& error);

}  // namespace rayo
