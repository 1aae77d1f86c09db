#include "core/image/output_encoding.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/error.h"
#include "core/path_util.h"

namespace OCIO = OCIO_NAMESPACE;

namespace rayo {

namespace {

const char* const kSupportedExtensions = ".exr, .png, .tif, .tiff, .jpg, .jpeg";

// Display value -> [0,1]; NaN becomes 0 so that a stray bad pixel cannot poison the quantiser.
float clamp01(float v) {
    return std::isnan(v) ? 0.0f : std::min(1.0f, std::max(0.0f, v));
}

// [0,1] RGBA -> unsigned integers of `channels` channels (alpha dropped when channels == 3).
template <typename T>
void quantise_to(const float* rgba, size_t pixels, int channels, T* out) {
    const float scale = static_cast<float>(std::numeric_limits<T>::max());
    // Values are clamped to [0,1] first: adding 0.5 and truncating rounds to nearest (lround is
    // slow).
    for (size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < channels; ++c)
            out[p * channels + c] = static_cast<T>(clamp01(rgba[p * 4 + c]) * scale + 0.5f);
}

}  // namespace

ImageFormat image_format_of(const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext == ".exr") return ImageFormat::Exr;
    if (ext == ".png") return ImageFormat::Png;
    if (ext == ".tif" || ext == ".tiff") return ImageFormat::Tiff;
    if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::Jpeg;
    throw InputError(
        path, "unsupported image extension '" + ext + "'; expected one of " + kSupportedExtensions);
}

int max_image_side(ImageFormat format) {
    // JPEG: 16-bit sides, and libjpeg's JPEG_MAX_DIMENSION is 65500. OpenEXR, PNG and TIFF
    // (BigTIFF above 2 GiB) take sides of 2^31 - 1; rayo's own limit is lower (core/camera.h).
    return format == ImageFormat::Jpeg ? 65500 : std::numeric_limits<int>::max();
}

ImageFileSpec image_spec(ImageFormat format, int width, int height, const OutputOptions& options) {
    ImageFileSpec spec;
    spec.width = width;
    spec.height = height;
    if (format == ImageFormat::Exr) {
        // Scene-linear, untouched: the film's floats, stored as float or half.
        spec.channels = 4;
        spec.type = options.half_float_exr ? PixelType::Half : PixelType::Float;
        if (!is_exr_compression(options.exr_compression))
            throw InputError("--exr-compression",
                             "unknown EXR compression '" + options.exr_compression +
                                 "'; expected one of " + exr_compression_names());
        spec.add("compression", options.exr_compression);
        // Rec.709 primaries and D65 white (x, y pairs: R, G, B, white), the film's space.
        spec.add("chromaticities",
                 std::vector<float>{0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f});
    } else {
        // JPEG has no alpha channel; PNG and TIFF keep it.
        spec.channels = format == ImageFormat::Jpeg ? 3 : 4;
        spec.type = format == ImageFormat::Tiff ? PixelType::UInt16 : PixelType::UInt8;
        // zlib level 1 and no row filter instead of OIIO's defaults: half the write time, files
        // ~14% larger (docs/performance.md); PNG stays lossless either way.
        if (format == ImageFormat::Png) {
            spec.add("png:compressionLevel", 1);
            spec.add("png:filter", 8);  // PNG_FILTER_NONE: no per-row filter search
        }
        // Classic TIFF offsets are 32-bit: big images need BigTIFF (docs/high-resolution.md).
        const size_t image_bytes = static_cast<size_t>(width) * static_cast<size_t>(height) *
                                   static_cast<size_t>(spec.channels) * 2;
        if (format == ImageFormat::Tiff && image_bytes >= (static_cast<size_t>(1) << 31))
            spec.add("tiff:bigtiff", 1);
        // Display pixels are unassociated already: OpenImageIO must not divide them by alpha.
        spec.add("oiio:UnassociatedAlpha", 1);
    }
    spec.add("Software", "rayo " RAYO_VERSION);
    for (const auto& [key, value] : options.metadata) {
        if (!key.empty()) spec.add(key, value);
    }
    return spec;
}

void normalize_channels(float* rgba, size_t pixels) {
    float max_value[3] = {0.0f, 0.0f, 0.0f};
    for (size_t i = 0; i < pixels * 4; i += 4)
        for (int c = 0; c < 3; ++c)
            if (std::isfinite(rgba[i + c])) max_value[c] = std::max(max_value[c], rgba[i + c]);
    for (size_t i = 0; i < pixels * 4; i += 4)
        for (int c = 0; c < 3; ++c)
            if (max_value[c] > 0.0f) rgba[i + c] /= max_value[c];
}

OCIO::ConstConfigRcPtr load_ocio_config() {
    const std::string path = ocio_config_path();
    try {
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(path.c_str());
        return config;
    } catch (const std::exception& e) {
        throw InputError(path, std::string("cannot load the OpenColorIO config: ") + e.what());
    }
}

std::string describe_display_views(const OCIO::ConstConfigRcPtr& config) {
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

void resolve_display_view(const OCIO::ConstConfigRcPtr& config, const std::string& where,
                          std::string& display, std::string& view) {
    if (display.empty()) display = config->getDefaultDisplay();
    bool display_found = false;
    for (int d = 0; d < config->getNumDisplays() && !display_found; ++d)
        display_found = display == config->getDisplay(d);
    if (!display_found)
        throw InputError(where,
                         "unknown OCIO display '" + display +
                             "'; valid display/view pairs: " + describe_display_views(config));
    if (view.empty()) view = config->getDefaultView(display.c_str());
    bool view_found = false;
    for (int v = 0; v < config->getNumViews(display.c_str()) && !view_found; ++v)
        view_found = view == config->getView(display.c_str(), v);
    if (!view_found)
        throw InputError(where,
                         "unknown OCIO view '" + view + "' for display '" + display +
                             "'; valid display/view pairs: " + describe_display_views(config));
}

DisplayEncoder::DisplayEncoder(ImageFormat format, const std::string& where,
                               const OutputOptions& options)
    : m_where(where),
      m_display(options.display),
      m_view(options.view),
      m_channels(format == ImageFormat::Jpeg ? 3 : 4),
      m_type(format == ImageFormat::Tiff ? PixelType::UInt16 : PixelType::UInt8) {
    const OCIO::ConstConfigRcPtr config = load_ocio_config();
    resolve_display_view(config, where, m_display, m_view);
    try {
        OCIO::DisplayViewTransformRcPtr transform = OCIO::DisplayViewTransform::Create();
        transform->setSrc(OCIO::ROLE_SCENE_LINEAR);
        transform->setDisplay(m_display.c_str());
        transform->setView(m_view.c_str());
        m_cpu = config->getProcessor(transform)->getDefaultCPUProcessor();
    } catch (const OCIO::Exception& e) {
        throw InputError(where,
                         "cannot apply OCIO view '" + m_display + "/" + m_view + "': " + e.what());
    }
}

void DisplayEncoder::unpremultiply(float* rgba, size_t pixels) {
    for (size_t i = 0; i < pixels * 4; i += 4) {
        const float alpha = rgba[i + 3];
        if (alpha > 0.0f && alpha < 1.0f)
            for (int c = 0; c < 3; ++c) rgba[i + c] /= alpha;
    }
}

void DisplayEncoder::apply_view(float* rgba, long width, long height) const {
    try {
        OCIO::PackedImageDesc image(rgba, width, height, 4);
        m_cpu->apply(image);
    } catch (const OCIO::Exception& e) {
        throw InputError(m_where,
                         "cannot apply OCIO view '" + m_display + "/" + m_view + "': " + e.what());
    }
}

void DisplayEncoder::quantise(const float* rgba, size_t pixels, void* out) const {
    if (m_type == PixelType::UInt16) {
        quantise_to(rgba, pixels, m_channels, static_cast<uint16_t*>(out));
    } else {
        quantise_to(rgba, pixels, m_channels, static_cast<uint8_t*>(out));
    }
}

}  // namespace rayo
