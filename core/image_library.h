#pragma once
// Image file I/O behind a loadable module (docs/architecture.md "The image module";
// docs/performance.md "Fixed costs"). Debian's libOpenImageIO pulls in ~260 shared libraries
// whose loading costs ~0.25 s and 130 MB, so no rayo executable links it: every OpenImageIO
// call goes through ImageLibrary, which the module `librayo_oiio.so` (core/oiio/) implements and
// the process loads with dlopen on first use. A command that never reads or writes an image
// (--version, --help, usage errors, `rayo info` of a scene without images) never loads it.
//
// The interface uses only standard types, so that OpenImageIO's stay inside the module. The
// module is built from the same sources and compiler as the executable; kImageLibraryAbi guards
// against a stale module from an older build or install.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rayo {

// Bumped whenever a class below changes.
constexpr int kImageLibraryAbi = 5;

enum class PixelType { Float, Half, UInt8, UInt16 };

// One metadata attribute of a file being written, in the order given (OpenImageIO's
// ImageSpec::attribute overloads: string, int, or an array of floats).
struct ImageAttribute {
    enum class Kind { Text, Integer, Floats };
    std::string name;
    Kind kind = Kind::Text;
    std::string text;
    int integer = 0;
    std::vector<float> floats;
};

// What a file holds: size, channels, pixel type, tiles (0: scanlines) and metadata.
struct ImageFileSpec {
    int width = 0, height = 0, channels = 0;
    PixelType type = PixelType::Float;
    int tile_size = 0;
    std::vector<ImageAttribute> attributes;

    void add(const std::string& name, const std::string& text) {
        attributes.push_back({name, ImageAttribute::Kind::Text, text, 0, {}});
    }
    void add(const std::string& name, int integer) {
        attributes.push_back({name, ImageAttribute::Kind::Integer, {}, integer, {}});
    }
    void add(const std::string& name, std::vector<float> floats) {
        attributes.push_back({name, ImageAttribute::Kind::Floats, {}, 0, std::move(floats)});
    }
};

// An open output file (OpenImageIO's ImageOutput). Each call returns false on failure, with the
// reason in error(). Not thread-safe: one thread at a time.
class ImageWriter {
  public:
    virtual ~ImageWriter() = default;
    // The whole image, `pixels` of `type` with the file's channels.
    virtual bool write_image(PixelType type, const void* pixels) = 0;
    // Float RGBA tiles covering [x0, x1) × [y0, y1) of a tiled file.
    virtual bool write_tiles(int x0, int x1, int y0, int y1, const float* rgba) = 0;
    // Scanlines [y0, y1), `pixels` of `type`.
    virtual bool write_scanlines(int y0, int y1, PixelType type, const void* pixels) = 0;
    virtual bool close() = 0;
    virtual std::string error() = 0;
};

// An image opened for reading from bytes in memory (which must outlive it).
class ImageReader {
  public:
    virtual ~ImageReader() = default;
    virtual int width() const = 0;
    virtual int height() const = 0;
    virtual int depth() const = 0;
    virtual int channels() const = 0;
    // The first `channels` channels of every pixel as floats (integer formats as value/max).
    virtual bool read_floats(int channels, float* out) = 0;
    virtual std::string error() = 0;
};

// What an image's header says (its first subimage, full resolution).
struct ImageHeader {
    int width = 0, height = 0, depth = 1, channels = 0;
    int bytes_per_channel = 1;  // as stored: 1 for 8-bit, 2 for 16-bit and half, 4 for float
    bool tiled = false;         // tiles the texture system reads one at a time (tiled EXR, TIFF)
    bool mipmapped = false;     // MIP levels in the file (maketx output)
    bool floating = false;      // float or half channels
    bool alpha = false;         // an alpha channel (or four channels)
};

enum class TextureWrapMode { Periodic, Clamp, Mirror };

// One texture system (OpenImageIO's TextureSystem with its own cache). add() and the queries are
// for one thread; lookup() is thread-safe.
class TextureCache {
  public:
    using Handle = const void*;
    virtual ~TextureCache() = default;
    // Registers an image read from `bytes` (which must outlive the cache) under `name` (its
    // extension picks the reader); never null, but good() tells whether it decodes.
    virtual Handle add(const std::string& name, const std::string& bytes) = 0;
    virtual bool good(Handle handle) const = 0;
    virtual bool floating_point(Handle handle) const = 0;
    // Whether the image has an alpha channel (colours are read unassociated: not premultiplied).
    virtual bool has_alpha(Handle handle) const = 0;
    // Filtered RGBA at (s, t) with the footprint's derivatives, trilinear between MIP levels,
    // bilinear within each or, with `bicubic`, bicubic; `fill` for missing channels.
    virtual void lookup(Handle handle, TextureWrapMode swrap, TextureWrapMode twrap, float fill,
                        bool bicubic, float s, float t, float dsdx, float dtdx, float dsdy,
                        float dtdy, float rgba[4]) const = 0;
    virtual int64_t memory_used() const = 0;
    virtual int64_t image_bytes() const = 0;
    // OpenImageIO's statistics text (the peak memory is read from it).
    virtual std::string statistics() const = 0;
};

// The module's entry point: everything rayo asks of OpenImageIO. Thread-safe.
class ImageLibrary {
  public:
    virtual ~ImageLibrary() = default;
    // Creates and opens `path` (format from its extension) for writing; null with the reason
    // in `error`.
    virtual std::unique_ptr<ImageWriter> create_writer(const std::string& path,
                                                       const ImageFileSpec& spec,
                                                       std::string& error) const = 0;
    // Opens `bytes` read from `path` (the reader is picked by the name; the bytes are read in
    // memory when the format can); null with the reason in `error`.
    virtual std::unique_ptr<ImageReader> open_reader(const std::string& path,
                                                     const std::string& bytes,
                                                     std::string& error) const = 0;
    // The header of `bytes` as an image, the reader picked by `name`'s extension, read before
    // any pixel is decoded; false with the reader's reason in `error`.
    virtual bool read_header(const std::string& name, const std::string& bytes, ImageHeader& header,
                             std::string& error) const = 0;
    // Whether every pixel of the image's first subimage decodes (a truncated or corrupt file
    // fails here, where the texture system would shade with what it half-decoded), read in
    // chunks of scanlines or tiles so that only the reader's own buffers grow with the image.
    virtual bool decodes(const std::string& name, const std::string& bytes,
                         std::string& error) const = 0;
    // Every pixel of the image's first subimage (the header read_header gave: width × height ×
    // channels values) into `out` as `type` (UInt8 or Float), colours as stored (not
    // premultiplied by alpha); false with the reader's reason in `error` when a pixel does not
    // decode (as decodes() would say).
    virtual bool read_texture_pixels(const std::string& name, const std::string& bytes,
                                     PixelType type, void* out, std::string& error) const = 0;
    // A new texture system whose cache holds at most `max_memory_mb` of decoded tiles, cutting
    // scanline images into tiles of `autotile` and building their MIP levels.
    virtual std::unique_ptr<TextureCache> create_texture_cache(float max_memory_mb,
                                                               int autotile) const = 0;
};

// The module's exported function: "rayo_image_library", returning the library for ABI `abi`
// (null for another ABI).
using ImageLibraryEntry = const ImageLibrary* (*)(int abi);
constexpr const char* kImageLibraryEntry = "rayo_image_library";
constexpr const char* kImageModuleName = "librayo_oiio.so";

// The module, loaded on the first call (by any thread; others wait for it). Looks in
// $RAYO_IMAGE_MODULE when set, else next to the executable, else in ../lib/rayo from it, else in
// the install directory.
// Throws InputError naming the paths tried and dlopen's reason when it cannot be loaded.
const ImageLibrary& image_library();

// Starts loading the module on a background thread and returns at once, so that the load
// overlaps other work (scene parsing, the render); image_library() then waits for it. A failure
// is reported by image_library(). Idempotent.
void preload_image_library();

// Throws image_library()'s error when no candidate path of the module exists, without loading
// it: check_output (core/image/image_output.h) calls it before a render, so that a missing
// module fails before the work (a module that exists but does not load fails at the first
// image call).
void check_image_library();

// Whether the module is loaded in this process (tests).
bool image_library_loaded();

}  // namespace rayo
