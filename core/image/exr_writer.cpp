// OpenEXR through its C++ library (OpenEXR 3.1: Imf::OutputFile for scanlines,
// Imf::TiledOutputFile for tiles; the file layout and attributes of "The OpenEXR File Layout" and
// "Reading and Writing OpenEXR Image Files", docs/references.md `openexr`).
#include "core/image/exr_writer.h"

#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFloatAttribute.h>
#include <ImfFloatVectorAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <ImfThreading.h>
#include <ImfTiledOutputFile.h>
#include <half.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace rayo {
namespace {

// OpenImageIO's names of OpenEXR's compressions (core/image/image_output.h's list).
bool exr_compression(const std::string& name, Imf::Compression& compression) {
    static const std::pair<const char*, Imf::Compression> kNames[] = {
        {"none", Imf::NO_COMPRESSION},   {"rle", Imf::RLE_COMPRESSION},
        {"zips", Imf::ZIPS_COMPRESSION}, {"zip", Imf::ZIP_COMPRESSION},
        {"piz", Imf::PIZ_COMPRESSION},   {"pxr24", Imf::PXR24_COMPRESSION},
        {"b44", Imf::B44_COMPRESSION},   {"b44a", Imf::B44A_COMPRESSION},
        {"dwaa", Imf::DWAA_COMPRESSION}, {"dwab", Imf::DWAB_COMPRESSION}};
    for (const auto& [known, value] : kNames) {
        if (name == known) {
            compression = value;
            return true;
        }
    }
    return false;
}

bool exr_line_order(const std::string& name, Imf::LineOrder& order) {
    if (name == "increasingY")
        order = Imf::INCREASING_Y;
    else if (name == "decreasingY")
        order = Imf::DECREASING_Y;
    else if (name == "randomY")
        order = Imf::RANDOM_Y;
    else
        return false;
    return true;
}

// "YYYY:MM:DD HH:MM:SS", local time: the form of OpenEXR's capDate attribute.
std::string capture_date() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &local);
    return text;
}

// Attributes named for another format or for OpenImageIO itself are not the file's.
bool foreign_attribute(const std::string& name) {
    for (const char* prefix : {"oiio:", "openexr:", "png:", "tiff:", "jpeg:"}) {
        if (name.compare(0, std::strlen(prefix), prefix) == 0) return true;
    }
    return false;
}

// The file as an Imf::OStream over stdio, keeping the first failure: OpenEXR writes the table of
// chunk offsets from its files' destructors, which swallow exceptions, so close() asks here.
class ExrFileStream : public Imf::OStream {
  public:
    ExrFileStream(const std::string& path, std::FILE* file)
        : Imf::OStream(path.c_str()), m_file(file) {}
    ~ExrFileStream() override {
        if (m_file != nullptr) std::fclose(m_file);
    }

    void write(const char c[], int n) override {
        if (std::fwrite(c, 1, static_cast<size_t>(n), m_file) != static_cast<size_t>(n))
            fail("cannot write");
    }
    uint64_t tellp() override {
        const off_t at = ::ftello(m_file);
        if (at < 0) fail("cannot tell the position");
        return static_cast<uint64_t>(at);
    }
    void seekp(uint64_t pos) override {
        if (::fseeko(m_file, static_cast<off_t>(pos), SEEK_SET) != 0) fail("cannot seek");
    }

    // Flushes and closes; false (the reason in failure(), errno in failure_errno()) when this or
    // an earlier call failed.
    bool close() {
        errno = 0;
        if (std::fflush(m_file) != 0 || std::ferror(m_file)) note("cannot write", errno);
        if (std::fclose(m_file) != 0) note("cannot close", errno);
        m_file = nullptr;
        return m_failure.empty();
    }
    const std::string& failure() const { return m_failure; }
    int failure_errno() const { return m_errno; }

  private:
    void note(const char* what, int error) {
        if (!m_failure.empty()) return;
        m_failure = what;
        m_errno = error;
    }
    [[noreturn]] void fail(const char* what) {
        note(what, errno);
        throw std::runtime_error(std::string(what) + " \"" + fileName() +
                                 "\": " + std::strerror(m_errno));
    }

    std::FILE* m_file;
    std::string m_failure;
    int m_errno = 0;
};

class ExrWriter : public ImageWriter {
  public:
    ExrWriter(const ImageFileSpec& spec, std::unique_ptr<ExrFileStream> stream)
        : m_width(spec.width),
          m_height(spec.height),
          m_channels(spec.channels),
          m_tile_size(spec.tile_size),
          m_file_type(spec.type),
          m_stream(std::move(stream)) {}

    // Writes the header; false with error() when OpenEXR refuses it.
    bool open(const Imf::Header& header) {
        return guarded([&] {
            if (m_tile_size > 0) {
                m_tiled = std::make_unique<Imf::TiledOutputFile>(*m_stream, header);
                m_tiles_left = static_cast<long long>(m_tiled->numXTiles()) * m_tiled->numYTiles();
            } else {
                m_scanlines = std::make_unique<Imf::OutputFile>(*m_stream, header);
            }
        });
    }

    bool write_image(PixelType type, const void* pixels) override {
        if (!pixels_are(type)) return false;
        const char* stored = as_stored(type, pixels, static_cast<size_t>(m_width) * m_height);
        const Imf::FrameBuffer buffer = frame_buffer(stored, 0, 0, m_width);
        return guarded([&] {
            if (m_tiled) {
                m_tiled->setFrameBuffer(buffer);
                m_tiled->writeTiles(0, m_tiled->numXTiles() - 1, 0, m_tiled->numYTiles() - 1);
                m_tiles_left = 0;
            } else {
                m_scanlines->setFrameBuffer(buffer);
                m_scanlines->writePixels(m_height - m_scanlines->currentScanLine());
            }
        });
    }

    bool write_tiles(int x0, int x1, int y0, int y1, const float* rgba) override {
        if (!m_tiled) {
            m_error = "the file is not tiled";
            return false;
        }
        if (x0 % m_tile_size != 0 || y0 % m_tile_size != 0 || x1 <= x0 || y1 <= y0 ||
            x1 > m_width || y1 > m_height) {
            m_error = "tiles must start on the tile grid and lie in the image";
            return false;
        }
        const int dx1 = x0 / m_tile_size, dx2 = (x1 - 1) / m_tile_size;
        const int dy1 = y0 / m_tile_size, dy2 = (y1 - 1) / m_tile_size;
        const char* stored =
            as_stored(PixelType::Float, rgba, static_cast<size_t>(x1 - x0) * (y1 - y0));
        const Imf::FrameBuffer buffer = frame_buffer(stored, x0, y0, x1 - x0);
        return guarded([&] {
            m_tiled->setFrameBuffer(buffer);
            m_tiled->writeTiles(dx1, dx2, dy1, dy2);
            m_tiles_left -= static_cast<long long>(dx2 - dx1 + 1) * (dy2 - dy1 + 1);
        });
    }

    bool write_scanlines(int y0, int y1, PixelType type, const void* pixels) override {
        if (!m_scanlines) {
            m_error = "the file is tiled";
            return false;
        }
        if (!pixels_are(type)) return false;
        if (y0 != m_scanlines->currentScanLine() || y1 < y0 || y1 > m_height) {
            m_error = "scanlines are written in order: row " +
                      std::to_string(m_scanlines->currentScanLine()) + " is next, not " +
                      std::to_string(y0);
            return false;
        }
        const char* stored = as_stored(type, pixels, static_cast<size_t>(m_width) * (y1 - y0));
        const Imf::FrameBuffer buffer = frame_buffer(stored, 0, y0, m_width);
        return guarded([&] {
            m_scanlines->setFrameBuffer(buffer);
            m_scanlines->writePixels(y1 - y0);
        });
    }

    bool close() override {
        if (!m_stream) return m_error.empty();
        bool ok = m_error.empty();
        if (ok && m_scanlines && m_scanlines->currentScanLine() != m_height) {
            m_error = "only " + std::to_string(m_scanlines->currentScanLine()) + " of the " +
                      std::to_string(m_height) + " scanlines were written";
            ok = false;
        }
        if (ok && m_tiled && m_tiles_left != 0) {
            m_error = std::to_string(m_tiles_left) + " tiles were not written";
            ok = false;
        }
        // The files write their chunk offset tables as they are destroyed.
        m_scanlines.reset();
        m_tiled.reset();
        const bool stream_ok = m_stream->close();
        if (ok && !stream_ok) {
            m_error = m_stream->failure() + " the file";
            errno = m_stream->failure_errno();
            ok = false;
        }
        m_stream.reset();
        return ok;
    }

    std::string error() override { return m_error; }

  private:
    // Runs OpenEXR calls; an exception is the error (errno as the failing write left it).
    template <typename F>
    bool guarded(F&& calls) {
        if (!m_error.empty()) return false;
        try {
            calls();
            return true;
        } catch (const std::exception& e) {
            m_error = e.what();
            if (m_stream && m_stream->failure_errno() != 0) errno = m_stream->failure_errno();
            return false;
        }
    }

    bool pixels_are(PixelType type) {
        if (type == PixelType::Float || type == PixelType::Half) return true;
        m_error = "an EXR file is written from half or float pixels";
        return false;
    }

    // `pixels` (`count` pixels of `type`) as the file's type: OpenEXR's output files take slices
    // of the channels' own type only. Floats become halves by Imath's conversion (round to
    // nearest even), as OpenImageIO converts them.
    const char* as_stored(PixelType type, const void* pixels, size_t count) {
        const size_t values = count * static_cast<size_t>(m_channels);
        if (type == m_file_type) return static_cast<const char*>(pixels);
        if (m_file_type == PixelType::Half) {
            const float* in = static_cast<const float*>(pixels);
            m_halves.resize(values);
            for (size_t i = 0; i < values; ++i) m_halves[i] = half(in[i]);
            return reinterpret_cast<const char*>(m_halves.data());
        }
        const half* in = static_cast<const half*>(pixels);
        m_floats.resize(values);
        for (size_t i = 0; i < values; ++i) m_floats[i] = static_cast<float>(in[i]);
        return reinterpret_cast<const char*>(m_floats.data());
    }

    // Slices for `pixels` of the file's type, rows of `row_width` pixels of m_channels values
    // whose first is the pixel (x0, y0): OpenEXR addresses a slice by the image's coordinates,
    // so the base is where pixel (0, 0) would be.
    Imf::FrameBuffer frame_buffer(const char* pixels, int x0, int y0, int row_width) const {
        const bool halves = m_file_type == PixelType::Half;
        const size_t value_bytes = halves ? 2 : 4;
        const size_t x_stride = value_bytes * m_channels;
        const size_t y_stride = x_stride * static_cast<size_t>(row_width);
        const char* origin = pixels -
                             static_cast<ptrdiff_t>(y0) * static_cast<ptrdiff_t>(y_stride) -
                             static_cast<ptrdiff_t>(x0) * static_cast<ptrdiff_t>(x_stride);
        static const char* const kNames[] = {"R", "G", "B", "A"};
        Imf::FrameBuffer buffer;
        for (int c = 0; c < m_channels; ++c) {
            buffer.insert(kNames[c], Imf::Slice(halves ? Imf::HALF : Imf::FLOAT,
                                                const_cast<char*>(origin) + c * value_bytes,
                                                x_stride, y_stride));
        }
        return buffer;
    }

    int m_width, m_height, m_channels, m_tile_size;
    PixelType m_file_type;
    std::vector<half> m_halves;  // the pixels converted to the file's type (as_stored)
    std::vector<float> m_floats;
    std::unique_ptr<ExrFileStream> m_stream;
    std::unique_ptr<Imf::OutputFile> m_scanlines;
    std::unique_ptr<Imf::TiledOutputFile> m_tiled;
    long long m_tiles_left = 0;
    std::string m_error;
};

// The header of `spec`; false with the reason in `error` for an attribute rayo cannot store.
bool exr_header(const ImageFileSpec& spec, Imf::Header& header, std::string& error) {
    header = Imf::Header(spec.width, spec.height);
    const Imf::PixelType type = spec.type == PixelType::Half ? Imf::HALF : Imf::FLOAT;
    static const char* const kNames[] = {"R", "G", "B", "A"};
    for (int c = 0; c < spec.channels; ++c) header.channels().insert(kNames[c], Imf::Channel(type));
    if (spec.tile_size > 0) {
        header.setTileDescription(
            Imf::TileDescription(spec.tile_size, spec.tile_size, Imf::ONE_LEVEL));
    }
    for (const ImageAttribute& a : spec.attributes) {
        if (a.name == "compression" && a.kind == ImageAttribute::Kind::Text) {
            if (!exr_compression(a.text, header.compression())) {
                error = "unknown EXR compression '" + a.text + "'";
                return false;
            }
            // OpenImageIO stores the DWA level it compresses with (OpenEXR's default, 45).
            if (header.compression() == Imf::DWAA_COMPRESSION ||
                header.compression() == Imf::DWAB_COMPRESSION)
                header.insert("dwaCompressionLevel", Imf::FloatAttribute(45.0f));
        } else if (a.name == "openexr:lineOrder" && a.kind == ImageAttribute::Kind::Text) {
            if (!exr_line_order(a.text, header.lineOrder())) {
                error = "unknown EXR line order '" + a.text + "'";
                return false;
            }
        } else if (a.name == "chromaticities" && a.kind == ImageAttribute::Kind::Floats &&
                   a.floats.size() == 8) {
            const std::vector<float>& f = a.floats;
            Imf::addChromaticities(
                header, Imf::Chromaticities(Imath::V2f(f[0], f[1]), Imath::V2f(f[2], f[3]),
                                            Imath::V2f(f[4], f[5]), Imath::V2f(f[6], f[7])));
        } else if (a.name.empty() || foreign_attribute(a.name)) {
            continue;
        } else if (a.kind == ImageAttribute::Kind::Text) {
            header.insert(a.name, Imf::StringAttribute(a.text));
        } else if (a.kind == ImageAttribute::Kind::Integer) {
            header.insert(a.name, Imf::IntAttribute(a.integer));
        } else if (a.floats.size() == 1) {
            header.insert(a.name, Imf::FloatAttribute(a.floats[0]));
        } else {
            header.insert(a.name, Imf::FloatVectorAttribute(a.floats));
        }
    }
    if (!Imf::hasCapDate(header)) Imf::addCapDate(header, capture_date());
    return true;
}

// One OpenEXR worker per core, as OpenImageIO's "exr_threads" default sets it: the tiles of one
// write_tiles call are compressed in parallel.
void start_exr_threads() {
    static std::once_flag once;
    std::call_once(once, [] {
        Imf::setGlobalThreadCount(
            static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
    });
}

}  // namespace

std::unique_ptr<ImageWriter> create_exr_writer(const std::string& path, const ImageFileSpec& spec,
                                               std::string& error) {
    if (spec.channels < 3 || spec.channels > 4 ||
        (spec.type != PixelType::Half && spec.type != PixelType::Float) || spec.width <= 0 ||
        spec.height <= 0 || spec.tile_size < 0) {
        error = "rayo writes EXR files of 3 or 4 half or float channels, not " +
                std::to_string(spec.channels) + " channels of this type";
        return nullptr;
    }
    Imf::Header header;
    try {
        if (!exr_header(spec, header, error)) return nullptr;
    } catch (const std::exception& e) {
        error = e.what();
        return nullptr;
    }
    start_exr_threads();
    errno = 0;
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (file == nullptr) {
        const int open_errno = errno;
        error = "cannot create \"" + path + "\"";
        errno = open_errno;
        return nullptr;
    }
    auto writer = std::make_unique<ExrWriter>(spec, std::make_unique<ExrFileStream>(path, file));
    if (!writer->open(header)) {
        const int open_errno = errno;
        error = writer->error();
        writer.reset();
        errno = open_errno;
        return nullptr;
    }
    return writer;
}

}  // namespace rayo
