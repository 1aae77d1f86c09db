// Film -> file. EXR keeps the scene-linear film untouched; PNG/TIFF/JPEG go through an OCIO
// display/view transform (docs/architecture.md "Output and colour"). Every format is written to a
// temporary file in the target directory and renamed onto the final path.
#include "core/image/image_output.h"

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imageio.h>
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
#include "core/image/interrupt_cleanup.h"
#include "core/path_util.h"

namespace OCIO = OCIO_NAMESPACE;

namespace rayo {

namespace {

enum class Format { Exr, Png, Tiff, Jpeg };

const char* const kSupportedExtensions = ".exr, .png, .tif, .tiff, .jpg, .jpeg";

Format format_of(const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext == ".exr") return Format::Exr;
    if (ext == ".png") return Format::Png;
    if (ext == ".tif" || ext == ".tiff") return Format::Tiff;
    if (ext == ".jpg" || ext == ".jpeg") return Format::Jpeg;
    throw InputError(
        path, "unsupported image extension '" + ext + "'; expected one of " + kSupportedExtensions);
}

bool file_exists(const char* path) {
    return std::ifstream(path).good();
}

OCIO::ConstConfigRcPtr load_config() {
    const std::string path = ocio_config_path();
    try {
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(path.c_str());
        return config;
    } catch (const std::exception& e) {
        throw InputError(path, std::string("cannot load the OpenColorIO config: ") + e.what());
    }
}

std::string describe(const OCIO::ConstConfigRcPtr& config) {
    std::string out;
    for (int d = 0; d < config->getNumDisplays(); ++d) {
        const char* display = config->getDisplay(d);
        for (int v = 0; v < config->getNumViews(display); ++v) {
            if (!out.empty()) out += ", ";
            out += std::string(display) + "/" + config->getView(display, v);
        }
    }
    return out.empty() ? "(none)" : out;
}

// Resolves empty names to the config's defaults and checks that the pair exists.
void resolve_display_view(const OCIO::ConstConfigRcPtr& config, const std::string& where,
                          std::string& display, std::string& view) {
    if (display.empty()) display = config->getDefaultDisplay();
    bool display_found = false;
    for (int d = 0; d < config->getNumDisplays() && !display_found; ++d)
        display_found = display == config->getDisplay(d);
    if (!display_found)
        throw InputError(where, "unknown OCIO display '" + display +
                                    "'; valid display/view pairs: " + describe(config));
    if (view.empty()) view = config->getDefaultView(display.c_str());
    bool view_found = false;
    for (int v = 0; v < config->getNumViews(display.c_str()) && !view_found; ++v)
        view_found = view == config->getView(display.c_str(), v);
    if (!view_found)
        throw InputError(where, "unknown OCIO view '" + view + "' for display '" + display +
                                    "'; valid display/view pairs: " + describe(config));
}

// Seed 000 ("Colour"): out-of-range values are either clamped, or the image is divided by its
// per-channel maximum. Non-finite values are ignored for the maximum.
void normalize_channels(std::vector<float>& rgba) {
    float max_value[3] = {0.0f, 0.0f, 0.0f};
    for (size_t i = 0; i < rgba.size(); i += 4)
        for (int c = 0; c < 3; ++c)
            if (std::isfinite(rgba[i + c])) max_value[c] = std::max(max_value[c], rgba[i + c]);
    for (size_t i = 0; i < rgba.size(); i += 4)
        for (int c = 0; c < 3; ++c)
            if (max_value[c] > 0.0f) rgba[i + c] /= max_value[c];
}

// The film's alpha is associated (premultiplied), as in EXR; display files store unassociated
// colour, and the view must see the colour itself, not colour x coverage.
void unpremultiply(std::vector<float>& rgba) {
    for (size_t i = 0; i < rgba.size(); i += 4) {
        const float alpha = rgba[i + 3];
        if (alpha > 0.0f && alpha < 1.0f)
            for (int c = 0; c < 3; ++c) rgba[i + c] /= alpha;
    }
}

// Display value -> [0,1]; NaN becomes 0 so that a stray bad pixel cannot poison the quantiser.
float clamp01(float v) {
    return std::isnan(v) ? 0.0f : std::min(1.0f, std::max(0.0f, v));
}

// The display-referred pixels (RGBA, [0,1]) of the film through (display, view).
std::vector<float> display_pixels(const Film& film, const std::string& where,
                                  const OutputOptions& options) {
    const OCIO::ConstConfigRcPtr config = load_config();
    std::string display = options.display;
    std::string view = options.view;
    resolve_display_view(config, where, display, view);

    std::vector<float> rgba = film.rgba();
    unpremultiply(rgba);
    if (options.range == RangeMode::Normalize) normalize_channels(rgba);
    try {
        OCIO::DisplayViewTransformRcPtr transform = OCIO::DisplayViewTransform::Create();
        transform->setSrc(OCIO::ROLE_SCENE_LINEAR);
        transform->setDisplay(display.c_str());
        transform->setView(view.c_str());
        OCIO::ConstCPUProcessorRcPtr cpu =
            config->getProcessor(transform)->getDefaultCPUProcessor();
        // One call over the whole image. (Rows in parallel through TBB were 0.05 s faster at
        // 2048², but TBB's hand-off is invisible to ThreadSanitizer, which then reports the
        // buffer made by this thread and read by TBB's already-running workers.)
        OCIO::PackedImageDesc image(rgba.data(), film.width(), film.height(), 4);
        cpu->apply(image);
    } catch (const OCIO::Exception& e) {
        throw InputError(where,
                         "cannot apply OCIO view '" + display + "/" + view + "': " + e.what());
    }
    for (float& v : rgba) v = clamp01(v);
    return rgba;
}

// [0,1] -> unsigned integers of `channels` channels (alpha dropped when channels == 3).
template <typename T>
std::vector<T> quantise(const std::vector<float>& rgba, int channels) {
    const float scale = static_cast<float>(std::numeric_limits<T>::max());
    std::vector<T> out(rgba.size() / 4 * channels);
    // Values are in [0,1] here: adding 0.5 and truncating rounds to nearest (lround is slow).
    const size_t pixels = rgba.size() / 4;
    for (size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < channels; ++c)
            out[p * channels + c] = static_cast<T>(rgba[p * 4 + c] * scale + 0.5f);
    return out;
}

// The longest file name the directory's file system takes (NAME_MAX, 255 on Linux file systems).
size_t max_name_length(const std::string& dir) {
    const long limit = ::pathconf(dir.c_str(), _PC_NAME_MAX);
    return limit > 0 ? static_cast<size_t>(limit) : 255;
}

std::string temporary_path_for(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    // "." + name + ".tmpPID" + the real extension (last, so that OpenImageIO picks the same
    // format); the name is shortened so that the temporary fits where the final name fits.
    const std::string suffix =
        ".tmp" + std::to_string(static_cast<long>(::getpid())) + lower_extension(path);
    const size_t limit = max_name_length(dir.empty() ? "." : dir);
    if (1 + name.size() + suffix.size() > limit) name.resize(limit - 1 - suffix.size());
    return dir + "." + name + suffix;
}

// OpenImageIO's message with the temporary name replaced by the final one (the name the user
// gave), and the system's reason appended when the message lacks one.
std::string write_failure(std::string message, int error, const std::string& tmp,
                          const std::string& path) {
    for (size_t at = message.find(tmp); at != std::string::npos; at = message.find(tmp, at)) {
        message.replace(at, tmp.size(), path);
        at += path.size();
    }
    if (message.empty()) message = "unknown error";
    if (error != 0 && message.find(std::strerror(error)) == std::string::npos) {
        message += std::string(" (") + std::strerror(error) + ")";
    }
    return message;
}

// Writes `pixels` (already in `type`) with `spec` to a temporary file, then renames it onto
// `path`. On failure the temporary is removed and InputError(path, "cannot write: ...") thrown;
// while it exists, SIGINT/SIGTERM remove it (core/image/interrupt_cleanup.h).
void write_atomically(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                      const void* pixels) {
    const std::string tmp = temporary_path_for(path);
    const TemporaryFileGuard guard(tmp);
    bool ok = false;
    std::string reason;
    int error = 0;
    {
        errno = 0;
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(tmp);
        if (!out) {
            error = errno;
            reason = OIIO::geterror();
        } else if (!out->open(tmp, spec)) {
            error = errno;
            reason = out->geterror();
        } else {
            ok = out->write_image(type, pixels);
            if (!ok) {
                error = errno;
                reason = out->geterror();
            }
            if (!out->close() && ok) {
                ok = false;
                error = errno;
                reason = out->geterror();
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

void add_metadata(OIIO::ImageSpec& spec, const OutputOptions& options) {
    spec.attribute("Software", "rayo " RAYO_VERSION);
    // Display pixels are unassociated already: OpenImageIO must not divide them by alpha again.
    if (spec.format != OIIO::TypeDesc::FLOAT && spec.format != OIIO::TypeDesc::HALF)
        spec.attribute("oiio:UnassociatedAlpha", 1);
    for (const auto& [key, value] : options.metadata) {
        if (!key.empty()) spec.attribute(key, value);
    }
}

}  // namespace

void check_output(const std::string& path, const OutputOptions& options) {
    const Format format = format_of(path);
    if (format != Format::Exr) {
        std::string display = options.display, view = options.view;
        resolve_display_view(load_config(), path, display, view);
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
    return describe(load_config());
}

void write_image(const Film& film, const std::string& path, const OutputOptions& options) {
    const Format format = format_of(path);
    if (film.width() <= 0 || film.height() <= 0)
        throw InputError(path, "cannot write: the image is empty (" + std::to_string(film.width()) +
                                   "x" + std::to_string(film.height()) + ")");

    if (format == Format::Exr) {
        // Scene-linear, untouched: the film's floats, stored as float or half.
        OIIO::ImageSpec spec(film.width(), film.height(), 4,
                             options.half_float_exr ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
        spec.attribute("compression", "zip");
        // Rec.709 primaries and D65 white (x, y pairs: R, G, B, white), the film's space.
        const float chromaticities[8] = {0.64f, 0.33f, 0.30f,   0.60f,
                                         0.15f, 0.06f, 0.3127f, 0.3290f};
        spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), chromaticities);
        add_metadata(spec, options);
        write_atomically(path, spec, OIIO::TypeDesc::FLOAT, film.rgba().data());
        return;
    }

    const std::vector<float> rgba = display_pixels(film, path, options);
    // JPEG has no alpha channel; PNG and TIFF keep it.
    const int channels = format == Format::Jpeg ? 3 : 4;
    if (format == Format::Tiff) {
        OIIO::ImageSpec spec(film.width(), film.height(), channels, OIIO::TypeDesc::UINT16);
        add_metadata(spec, options);
        const std::vector<uint16_t> pixels = quantise<uint16_t>(rgba, channels);
        write_atomically(path, spec, OIIO::TypeDesc::UINT16, pixels.data());
    } else {
        OIIO::ImageSpec spec(film.width(), film.height(), channels, OIIO::TypeDesc::UINT8);
        // zlib level 1 and no row filter instead of OIIO's defaults: half the write time, files
        // ~14% larger (docs/performance.md); PNG stays lossless either way.
        if (format == Format::Png) {
            spec.attribute("png:compressionLevel", 1);
            spec.attribute("png:filter", 8);  // PNG_FILTER_NONE: no per-row filter search
        }
        add_metadata(spec, options);
        const std::vector<uint8_t> pixels = quantise<uint8_t>(rgba, channels);
        write_atomically(path, spec, OIIO::TypeDesc::UINT8, pixels.data());
    }
}

}  // namespace rayo
