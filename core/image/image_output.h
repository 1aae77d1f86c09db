#pragma once
// Writes the film: EXR untouched (scene-linear, float or half, with metadata); PNG/TIFF/JPEG
// through an OpenColorIO display/view transform. Files are written to a temporary name in the
// target directory and renamed, so a failure never leaves a partial file under the final name.
#include <map>
#include <string>
#include <vector>

#include "core/film.h"

namespace rayo {

enum class RangeMode {
    Clamp,      // display values clamped to [0,1] (seed 000, first option)
    Normalize,  // the whole image divided by its per-channel maximum before the view (seed 000)
};

// Which library writes PNG and EXR files (--image-writer; core/image/image_writers.h): libpng and
// OpenEXR directly, or OpenImageIO through the image module, the reference writer. TIFF and JPEG
// are always OpenImageIO's.
enum class ImageWriterChoice { Direct, OpenImageIO };

struct OutputOptions {
    std::string display;  // empty: the config's default display
    std::string view;     // empty: the display's default view
    RangeMode range = RangeMode::Clamp;
    bool half_float_exr = false;
    // The EXR compression (--exr-compression), one of exr_compression_names(); kept in the file's
    // "compression" attribute. zip: lossless and fast enough to overlap the render
    // (docs/performance.md "EXR output").
    std::string exr_compression = "zip";
    ImageWriterChoice writer = ImageWriterChoice::Direct;
    std::map<std::string, std::string> metadata;  // e.g. "rayo:scene", "rayo:spp", "Software"
};

// The compressions OpenEXR 3.1 offers, for --exr-compression and its error messages: lossless
// none, rle, zips, zip, piz; lossy pxr24 (floats kept to 24 bits), b44 and b44a (half channels
// only: float channels are stored uncompressed), dwaa and dwab (DCT, lossy colour).
std::string exr_compression_names();
// The same names as a list (--exr-compression's choices and --help).
std::vector<std::string> exr_compression_list();
bool is_exr_compression(const std::string& name);

// The OCIO config rayo uses: $OCIO when set, else the shipped config (installed or source tree).
std::string ocio_config_path();

// Everything about writing `path` that does not need the pixels, checked before a render so
// that a typo in the output name does not throw the render away: a known extension, the
// display/view (display formats), a directory that exists, is a directory and is writable, a
// path that is not a directory, and a file name the file system takes (the temporary name is
// shortened to fit). Throws InputError naming the path and the reason (std::runtime_error when
// the image module is missing: core/image_library.h, check_image_library).
void check_output(const std::string& path, const OutputOptions& options);

// Throws InputError (where = the path) for an unknown extension, an unknown display/view or an
// unwritable location; the final file exists only when the call succeeds.
void write_image(const Film& film, const std::string& path, const OutputOptions& options);

// Lists "display/view" pairs of the active config (for --help and errors).
std::string describe_displays_and_views();

}  // namespace rayo
