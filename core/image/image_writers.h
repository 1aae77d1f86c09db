#pragma once
// Which library writes an image file (docs/performance.md "Writing PNG and EXR without
// OpenImageIO"): PNG and EXR are written with libpng and OpenEXR directly (core/image/png_writer.h,
// core/image/exr_writer.h), so that a render writing them never loads the image module and its
// ~260 libraries; TIFF and JPEG, and PNG/EXR under ImageWriterChoice::OpenImageIO (the reference
// writer the tests compare with), through the image module (core/image_library.h). Both kinds
// implement ImageWriter: the in-memory and the streamed output do not tell them apart.
#include <memory>
#include <string>

#include "core/image/image_output.h"
#include "core/image_library.h"

namespace rayo {

// Whether writing `path` (its extension) with `choice` goes through the image module.
bool writer_needs_image_library(const std::string& path, ImageWriterChoice choice);

// Creates `file` (the format from its extension) and opens it for writing with the writer
// `choice` picks; null with the reason in `error` (errno kept from the failing call). Throws
// image_library()'s error when the image module is needed and cannot be loaded.
std::unique_ptr<ImageWriter> create_image_writer(const std::string& file, const ImageFileSpec& spec,
                                                 ImageWriterChoice choice, std::string& error);

}  // namespace rayo
