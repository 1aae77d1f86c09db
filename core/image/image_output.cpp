// Film -> file. EXR keeps the scene-linear film untouched; PNG/TIFF/JPEG go through an OCIO
// display/view transform (docs/architecture.md "Output and colour"). Every format is written to a
// temporary file in the target directory and renamed onto the final path.
#include "core/image/image_output.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <vector>

#include "core/error.h"
#include "core/image/atomic_file.h"
#include "core/image/image_writers.h"
#include "core/image/interrupt_cleanup.h"
#include "core/image/output_encoding.h"
#include "core/image_library.h"
#include "core/path_util.h"

namespace rayo {

namespace {

bool file_exists(const char* path) {
    return std::ifstream(path).good();
}

// Writes `pixels` (already in `type`) with `spec` to a temporary file, then renames it onto
// `path`. On failure the temporary is removed and InputError(path, "cannot write: ...") thrown;
// while it exists, SIGINT/SIGTERM remove it (core/image/interrupt_cleanup.h).
void write_atomically(const std::string& path, const ImageFileSpec& spec, PixelType type,
                      const void* pixels, ImageWriterChoice choice) {
    const std::string tmp = temporary_path_for(path);
    const TemporaryFileGuard guard(tmp);
    bool ok = false;
    std::string reason;
    int error = 0;
    {
        errno = 0;
        std::unique_ptr<ImageWriter> out = create_image_writer(tmp, spec, choice, reason);
        if (!out) {
            error = errno;
        } else {
            ok = out->write_image(type, pixels);
            if (!ok) {
                error = errno;
                reason = out->error();
            }
            if (!out->close() && ok) {
                ok = false;
                error = errno;
                reason = out->error();
            }
        }
    }
    if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) {
        ok = false;
        error = errno;
        reason = "cannot rename the temporary file";
    }
    if (!ok) {
        std::remove(tmp.c_str());
        throw InputError(path, "cannot write: " + write_failure(reason, error, tmp, path));
    }
}

// OpenEXR 3.1's compressions (Imf::Compression), by OpenImageIO's names.
const char* const kExrCompressions[] = {"none",  "rle", "zips", "zip",  "piz",
                                        "pxr24", "b44", "b44a", "dwaa", "dwab"};

}  // namespace

std::string exr_compression_names() {
    std::string names;
    for (const char* name : kExrCompressions)
        names += (names.empty() ? "" : ", ") + std::string(name);
    return names;
}

std::vector<std::string> exr_compression_list() {
    return {std::begin(kExrCompressions), std::end(kExrCompressions)};
}

bool is_exr_compression(const std::string& name) {
    return std::find(std::begin(kExrCompressions), std::end(kExrCompressions), name) !=
           std::end(kExrCompressions);
}

void check_output(const std::string& path, const OutputOptions& options) {
    const ImageFormat format = image_format_of(path);
    if (writer_needs_image_library(path, options.writer)) check_image_library();
    if (format != ImageFormat::Exr) {
        std::string display = options.display, view = options.view;
        resolve_display_view(load_ocio_config(), path, display, view);
    }
    const std::string dir = parent_directory(path);
    struct stat info {};
    if (::stat(dir.c_str(), &info) != 0) {
        throw InputError(path, "cannot write: the directory '" + dir + "' does not exist (" +
                                   std::strerror(errno) + ")");
    }
    if (!S_ISDIR(info.st_mode)) {
        throw InputError(path, "cannot write: '" + dir + "' is not a directory");
    }
    if (::access(dir.c_str(), W_OK) != 0) {
        throw InputError(path, "cannot write: the directory '" + dir + "' is not writable (" +
                                   std::strerror(errno) + ")");
    }
    if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) {
        throw InputError(path, "cannot write: it is a directory");
    }
    const size_t slash = path.find_last_of('/');
    const size_t name_length = slash == std::string::npos ? path.size() : path.size() - slash - 1;
    const size_t limit = max_name_length(dir);
    if (name_length > limit) {
        throw InputError(path, "cannot write: the file name is " + std::to_string(name_length) +
                                   " bytes; the file system allows at most " +
                                   std::to_string(limit));
    }
}

std::string ocio_config_path() {
    const char* env = std::getenv("OCIO");
    if (env != nullptr && env[0] != '\0') return env;
    if (file_exists(RAYO_OCIO_CONFIG_INSTALL)) return RAYO_OCIO_CONFIG_INSTALL;
    return RAYO_OCIO_CONFIG_SOURCE;
}

std::string describe_displays_and_views() {
    return describe_display_views(load_ocio_config());
}

void write_image(const Film& film, const std::string& path, const OutputOptions& options) {
    const ImageFormat format = image_format_of(path);
    if (film.width() <= 0 || film.height() <= 0)
        throw InputError(path, "cannot write: the image is empty (" + std::to_string(film.width()) +
                                   "x" + std::to_string(film.height()) + ")");
    const ImageFileSpec spec = image_spec(format, film.width(), film.height(), options);
    if (format == ImageFormat::Exr) {
        write_atomically(path, spec, PixelType::Float, film.rgba().data(), options.writer);
        return;
    }
    // Display formats: the view over a copy of the film (normalized first when asked), then
    // quantised. One OCIO call over the whole image. (Rows in parallel through TBB were 0.05 s
    // faster at 2048², but TBB's hand-off is invisible to ThreadSanitizer, which then reports the
    // buffer made by this thread and read by TBB's already-running workers.)
    const DisplayEncoder encoder(format, path, options);
    std::vector<float> rgba = film.rgba();
    const size_t pixels = rgba.size() / 4;
    DisplayEncoder::unpremultiply(rgba.data(), pixels);
    if (options.range == RangeMode::Normalize) normalize_channels(rgba.data(), pixels);
    encoder.apply_view(rgba.data(), film.width(), film.height());
    std::vector<unsigned char> bytes(pixels * encoder.bytes_per_pixel());
    encoder.quantise(rgba.data(), pixels, bytes.data());
    write_atomically(path, spec, encoder.type(), bytes.data(), options.writer);
}

}  // namespace rayo
