#pragma once
// How rayo encodes an image file, shared by the in-memory writer (core/image/image_output.h) and
// the streaming one (core/image/tile_stream.h) so that both write the same pixels and metadata:
// the format from the extension, the file spec of each format, and the display encoding
// of PNG/TIFF/JPEG (unpremultiply, the OCIO display/view, clamp, quantise). Every step of the
// display encoding works pixel by pixel, so a tile encodes to the same bytes as the same pixels
// of the whole image.
#include <OpenColorIO/OpenColorIO.h>

#include <cstddef>
#include <string>

#include "core/image/image_output.h"
#include "core/image_library.h"

namespace rayo {

enum class ImageFormat { Exr, Png, Tiff, Jpeg };

// The format of `path` from its extension; InputError(path) for an unknown one.
ImageFormat image_format_of(const std::string& path);

// The largest side each format takes (JPEG stores sides in 16 bits and libjpeg stops at 65500).
int max_image_side(ImageFormat format);

// The spec rayo writes: EXR scene-linear float or half with chromaticities, the compression of
// `options` (InputError for an unknown one); PNG/JPEG 8-bit,
// TIFF 16-bit, display-referred; the metadata of `options` on every format.
ImageFileSpec image_spec(ImageFormat format, int width, int height, const OutputOptions& options);

// Seed 000 ("Colour"): divides colour by its per-channel maximum over the `pixels` RGBA pixels
// (non-finite values ignored); the option `--range normalize`.
void normalize_channels(float* rgba, size_t pixels);

// Scene-linear float RGBA (associated alpha) -> the quantised display pixels of a PNG, TIFF or
// JPEG file through one OCIO display/view. Const and thread-safe once built.
class DisplayEncoder {
  public:
    // Loads the OCIO config and the display/view (empty: the config's defaults); InputError
    // naming `where` for an unknown one.
    DisplayEncoder(ImageFormat format, const std::string& where, const OutputOptions& options);

    int channels() const { return m_channels; }  // 3 for JPEG (no alpha), else 4
    PixelType type() const { return m_type; }
    size_t bytes_per_pixel() const { return m_channels * (m_type == PixelType::UInt16 ? 2 : 1); }

    // Unassociates alpha in place (the view must see colour, not colour × coverage).
    static void unpremultiply(float* rgba, size_t pixels);
    // In place: display-referred [0,1] through the view (rows of `width`, `height` rows).
    void apply_view(float* rgba, long width, long height) const;
    // [0,1] RGBA -> `pixels` pixels of channels() values of type() at `out`.
    void quantise(const float* rgba, size_t pixels, void* out) const;

  private:
    std::string m_where, m_display, m_view;
    int m_channels;
    PixelType m_type;
    OCIO_NAMESPACE::ConstCPUProcessorRcPtr m_cpu;
};

// The OCIO config's display/view pairs; check_output's and --help's list.
std::string describe_display_views(const OCIO_NAMESPACE::ConstConfigRcPtr& config);
// The active config (ocio_config_path()); InputError when it cannot be loaded.
OCIO_NAMESPACE::ConstConfigRcPtr load_ocio_config();
// Resolves empty names to the config's defaults; InputError(where) for an unknown pair.
void resolve_display_view(const OCIO_NAMESPACE::ConstConfigRcPtr& config, const std::string& where,
                          std::string& display, std::string& view);

}  // namespace rayo
