// The image module librayo_oiio.so: core/image_library.h implemented with OpenImageIO. The only
// rayo code that includes OpenImageIO's headers; it depends on nothing of rayo but that header,
// so that it is built on its own as position-independent code and loaded with dlopen by the
// executable on first use (docs/architecture.md "The image module").
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cerrno>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image_library.h"

namespace rayo {
namespace {

OIIO::TypeDesc oiio_type(PixelType type) {
    switch (type) {
        case PixelType::Half:
            return OIIO::TypeDesc::HALF;
        case PixelType::UInt8:
            return OIIO::TypeDesc::UINT8;
        case PixelType::UInt16:
            return OIIO::TypeDesc::UINT16;
        case PixelType::Float:
            break;
    }
    return OIIO::TypeDesc::FLOAT;
}

OIIO::TextureOpt::Wrap oiio_wrap(TextureWrapMode wrap) {
    switch (wrap) {
        case TextureWrapMode::Clamp:
            return OIIO::TextureOpt::WrapClamp;
        case TextureWrapMode::Mirror:
            return OIIO::TextureOpt::WrapMirror;
        case TextureWrapMode::Periodic:
            break;
    }
    return OIIO::TextureOpt::WrapPeriodic;
}

OIIO::ImageSpec oiio_spec(const ImageFileSpec& file) {
    OIIO::ImageSpec spec(file.width, file.height, file.channels, oiio_type(file.type));
    if (file.tile_size > 0) {
        spec.tile_width = file.tile_size;
        spec.tile_height = file.tile_size;
    }
    for (const ImageAttribute& a : file.attributes) {
        switch (a.kind) {
            case ImageAttribute::Kind::Text:
                spec.attribute(a.name, a.text);
                break;
            case ImageAttribute::Kind::Integer:
                spec.attribute(a.name, a.integer);
                break;
            case ImageAttribute::Kind::Floats:
                spec.attribute(
                    a.name,
                    OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, static_cast<int>(a.floats.size())),
                    a.floats.data());
                break;
        }
    }
    return spec;
}

class OiioWriter : public ImageWriter {
  public:
    explicit OiioWriter(std::unique_ptr<OIIO::ImageOutput> out) : m_out(std::move(out)) {}

    bool write_image(PixelType type, const void* pixels) override {
        return m_out->write_image(oiio_type(type), pixels);
    }
    bool write_tiles(int x0, int x1, int y0, int y1, const float* rgba) override {
        return m_out->write_tiles(x0, x1, y0, y1, 0, 1, OIIO::TypeDesc::FLOAT, rgba);
    }
    bool write_scanlines(int y0, int y1, PixelType type, const void* pixels) override {
        return m_out->write_scanlines(y0, y1, 0, oiio_type(type), pixels);
    }
    bool close() override { return m_out->close(); }
    std::string error() override { return m_out->geterror(); }

  private:
    std::unique_ptr<OIIO::ImageOutput> m_out;
};

class OiioReader : public ImageReader {
  public:
    OiioReader(std::unique_ptr<OIIO::ImageInput> in,
               std::unique_ptr<OIIO::Filesystem::IOMemReader> memory)
        : m_memory(std::move(memory)), m_in(std::move(in)) {}

    int width() const override { return m_in->spec().width; }
    int height() const override { return m_in->spec().height; }
    int depth() const override { return m_in->spec().depth; }
    int channels() const override { return m_in->spec().nchannels; }
    bool read_floats(int channels, float* out) override {
        return m_in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, out);
    }
    std::string error() override { return m_in->geterror(); }

  private:
    std::unique_ptr<OIIO::Filesystem::IOMemReader> m_memory;  // outlives the input
    std::unique_ptr<OIIO::ImageInput> m_in;
};

class OiioTextureCache : public TextureCache {
  public:
    OiioTextureCache(float max_memory_mb, int autotile)
        : m_system(OIIO::TextureSystem::create(/*shared=*/false)) {
        // A private system: its cache limit and statistics are this render's.
        m_system->attribute("max_memory_MB", max_memory_mb);
        m_system->attribute("autotile", autotile);
        m_system->attribute("automip", 1);
        m_system->attribute("gray_to_rgb", 1);
    }
    ~OiioTextureCache() override { OIIO::TextureSystem::destroy(m_system); }

    Handle add(const std::string& name, const std::string& bytes) override {
        // The image's bytes through an in-memory proxy that lives as long as the system (the
        // cache may reopen it).
        m_proxies.push_back(
            std::make_unique<OIIO::Filesystem::IOMemReader>(bytes.data(), bytes.size()));
        const OIIO::ustring key(name);
        OIIO::ImageSpec config;
        void* proxy = m_proxies.back().get();
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        // Colour as stored, not premultiplied by alpha (glTF and PNG colours are unassociated;
        // alpha is coverage for cutouts, docs/models.md).
        config.attribute("oiio:UnassociatedAlpha", 1);
        m_system->imagecache()->add_file(key, nullptr, &config);
        return m_system->get_texture_handle(key);
    }
    bool good(Handle handle) const override { return m_system->good(texture_handle(handle)); }
    bool floating_point(Handle handle) const override {
        const OIIO::ImageSpec* spec = m_system->imagespec(texture_handle(handle), nullptr);
        return spec != nullptr && spec->format.is_floating_point();
    }
    bool has_alpha(Handle handle) const override {
        const OIIO::ImageSpec* spec = m_system->imagespec(texture_handle(handle), nullptr);
        return spec != nullptr && (spec->alpha_channel >= 0 || spec->nchannels == 4);
    }
    void lookup(Handle handle, TextureWrapMode swrap, TextureWrapMode twrap, float fill,
                bool bicubic, float s, float t, float dsdx, float dtdx, float dsdy, float dtdy,
                float rgba[4]) const override {
        OIIO::TextureOpt options;
        options.swrap = oiio_wrap(swrap);
        options.twrap = oiio_wrap(twrap);
        options.fill = fill;
        // rayo's own MIP maps' filter (shading/mip_pyramid.h): trilinear, bilinear within a
        // level unless bicubic is asked for.
        options.mipmode = OIIO::TextureOpt::MipModeTrilinear;
        options.interpmode =
            bicubic ? OIIO::TextureOpt::InterpBicubic : OIIO::TextureOpt::InterpBilinear;
        m_system->texture(texture_handle(handle), m_system->get_perthread_info(), options, s, t,
                          dsdx, dtdx, dsdy, dtdy, 4, rgba);
    }
    int64_t memory_used() const override { return stat("stat:cache_memory_used"); }
    int64_t image_bytes() const override { return stat("stat:image_size"); }
    std::string statistics() const override { return m_system->imagecache()->getstats(1); }

  private:
    static OIIO::TextureSystem::TextureHandle* texture_handle(Handle handle) {
        return static_cast<OIIO::TextureSystem::TextureHandle*>(const_cast<void*>(handle));
    }
    int64_t stat(const char* name) const {
        int64_t value = 0;
        return m_system->imagecache()->getattribute(name, OIIO::TypeDesc::INT64, &value) ? value
                                                                                         : 0;
    }

    OIIO::TextureSystem* m_system;
    std::vector<std::unique_ptr<OIIO::Filesystem::IOMemReader>> m_proxies;
};

// `bytes` opened as an image through an in-memory proxy (which must outlive the input).
std::unique_ptr<OIIO::ImageInput> open_memory(const std::string& name,
                                              OIIO::Filesystem::IOMemReader& memory,
                                              std::string& error, bool unassociated = false) {
    OIIO::ImageSpec config;
    void* proxy = &memory;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    if (unassociated) config.attribute("oiio:UnassociatedAlpha", 1);
    auto input = OIIO::ImageInput::open(name, &config);
    if (!input) error = OIIO::geterror();
    return input;
}

class OiioImageLibrary : public ImageLibrary {
  public:
    std::unique_ptr<ImageWriter> create_writer(const std::string& path, const ImageFileSpec& spec,
                                               std::string& error) const override {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
        if (!out) {
            error = OIIO::geterror();
            return nullptr;
        }
        if (!out->open(path, oiio_spec(spec))) {
            const int open_errno = errno;  // the caller reports the system's reason
            error = out->geterror();
            out.reset();
            errno = open_errno;
            return nullptr;
        }
        return std::make_unique<OiioWriter>(std::move(out));
    }

    std::unique_ptr<ImageReader> open_reader(const std::string& path, const std::string& bytes,
                                             std::string& error) const override {
        // Decoded from the bytes (not reopened by name), when the format can.
        auto memory = std::make_unique<OIIO::Filesystem::IOMemReader>(bytes.data(), bytes.size());
        auto input = OIIO::ImageInput::create(path);
        if (!input) {
            error = OIIO::geterror();
            return nullptr;
        }
        if (input->supports("ioproxy")) input->set_ioproxy(memory.get());
        OIIO::ImageSpec spec, config;
        if (!input->open(path, spec, config)) {
            error = input->geterror();
            return nullptr;
        }
        return std::make_unique<OiioReader>(std::move(input), std::move(memory));
    }

    // A reader's exception (OpenImageIO's GIF reader resizes a vector to what a header declares:
    // std::length_error; found by fuzz/texture_fuzz.cpp) is its error, as the interface says.
    bool read_header(const std::string& name, const std::string& bytes, ImageHeader& header,
                     std::string& error) const override {
        try {
            return read_header_or_throw(name, bytes, header, error);
        } catch (const std::exception& e) {
            error = std::string("the image's reader failed: ") + e.what();
            return false;
        }
    }

    bool decodes(const std::string& name, const std::string& bytes,
                 std::string& error) const override {
        try {
            return decodes_or_throw(name, bytes, error);
        } catch (const std::exception& e) {
            error = std::string("the image's reader failed: ") + e.what();
            return false;
        }
    }

  private:
    static bool read_header_or_throw(const std::string& name, const std::string& bytes,
                                     ImageHeader& header, std::string& error) {
        OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
        std::unique_ptr<OIIO::ImageInput> input = open_memory(name, memory, error);
        if (!input) return false;
        const OIIO::ImageSpec& spec = input->spec();
        header.width = spec.width;
        header.height = spec.height;
        header.depth = std::max(spec.depth, 1);
        header.channels = spec.nchannels;
        header.bytes_per_channel = static_cast<int>(spec.format.basesize());
        header.tiled = spec.tile_width > 0;
        header.floating = spec.format.is_floating_point();
        header.alpha = spec.alpha_channel >= 0 || spec.nchannels == 4;
        header.mipmapped = input->seek_subimage(0, 1);
        input->close();
        return true;
    }

    static bool decodes_or_throw(const std::string& name, const std::string& bytes,
                                 std::string& error) {
        OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
        std::unique_ptr<OIIO::ImageInput> input = open_memory(name, memory, error);
        if (!input) return false;
        const OIIO::ImageSpec spec = input->spec();
        // Rows of whole tiles (or scanlines) up to about 16 MB of native pixels at a time.
        const size_t row_bytes = std::max<size_t>(spec.scanline_bytes(true), 1);
        const int step = spec.tile_height > 0 ? spec.tile_height : 1;
        const int rows =
            std::max(step, static_cast<int>((size_t(16) << 20) / row_bytes) / step * step);
        std::vector<unsigned char> chunk;
        bool ok = true;
        for (int z = spec.z; ok && z < spec.z + std::max(spec.depth, 1); ++z) {
            for (int y = spec.y; ok && y < spec.y + spec.height; y += rows) {
                const int end = std::min(y + rows, spec.y + spec.height);
                chunk.resize(row_bytes * size_t(end - y));
                ok = spec.tile_width > 0
                         ? input->read_tiles(0, 0, spec.x, spec.x + spec.width, y, end, z, z + 1, 0,
                                             spec.nchannels, OIIO::TypeUnknown, chunk.data())
                         : input->read_scanlines(0, 0, y, end, z, 0, spec.nchannels,
                                                 OIIO::TypeUnknown, chunk.data());
            }
        }
        // Some readers (libpng's through OpenImageIO) report a broken stream as an error message
        // while returning the pixels they could make.
        const std::string message = input->geterror();
        input->close();
        if (ok && message.empty()) return true;
        error = message.empty() ? "the image does not decode" : message;
        return false;
    }

    static bool read_texture_pixels_or_throw(const std::string& name, const std::string& bytes,
                                             PixelType type, void* out, std::string& error) {
        OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
        // Colour as stored, not premultiplied by alpha, as the texture cache reads it.
        std::unique_ptr<OIIO::ImageInput> input =
            open_memory(name, memory, error, /*unassociated=*/true);
        if (!input) return false;
        const OIIO::ImageSpec spec = input->spec();
        const bool ok = input->read_image(0, 0, 0, spec.nchannels, oiio_type(type), out);
        // As in decodes(): libpng's errors may come as a message beside pixels.
        const std::string message = input->geterror();
        input->close();
        if (ok && message.empty()) return true;
        error = message.empty() ? "the image does not decode" : message;
        return false;
    }

  public:
    bool read_texture_pixels(const std::string& name, const std::string& bytes, PixelType type,
                             void* out, std::string& error) const override {
        try {
            return read_texture_pixels_or_throw(name, bytes, type, out, error);
        } catch (const std::exception& e) {
            error = std::string("the image's reader failed: ") + e.what();
            return false;
        }
    }

    std::unique_ptr<TextureCache> create_texture_cache(float max_memory_mb,
                                                       int autotile) const override {
        return std::make_unique<OiioTextureCache>(max_memory_mb, autotile);
    }
};

}  // namespace
}  // namespace rayo

extern "C" __attribute__((visibility("default"))) const rayo::ImageLibrary* rayo_image_library(
    int abi) {
    static const rayo::OiioImageLibrary library;
    return abi == rayo::kImageLibraryAbi ? &library : nullptr;
}
