// PNG through libpng (the PNG specification, ISO/IEC 15948, and libpng's manual, docs/references.md
// `png-spec`: the write sequence IHDR, ancillary chunks, png_write_info, rows, png_write_end).
// libpng reports errors by longjmp to the setjmp of the call that failed: every method that calls
// libpng sets one, with no C++ object of its own alive between the setjmp and the calls.
#include "core/image/png_writer.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

namespace rayo {
namespace {

const char* type_name(PixelType type) {
    switch (type) {
        case PixelType::UInt8:
            return "8-bit";
        case PixelType::UInt16:
            return "16-bit";
        case PixelType::Half:
            return "half";
        case PixelType::Float:
            break;
    }
    return "float";
}

int png_colour_type(int channels) {
    switch (channels) {
        case 1:
            return PNG_COLOR_TYPE_GRAY;
        case 2:
            return PNG_COLOR_TYPE_GRAY_ALPHA;
        case 3:
            return PNG_COLOR_TYPE_RGB;
        default:
            return PNG_COLOR_TYPE_RGB_ALPHA;
    }
}

class PngWriter : public ImageWriter {
  public:
    PngWriter(const ImageFileSpec& spec)
        : m_width(spec.width),
          m_height(spec.height),
          m_type(spec.type),
          m_row_bytes(static_cast<size_t>(spec.width) * spec.channels *
                      (spec.type == PixelType::UInt16 ? 2 : 1)) {}

    ~PngWriter() override {
        if (m_png != nullptr) png_destroy_write_struct(&m_png, &m_info);
        if (m_file != nullptr) std::fclose(m_file);
    }

    // Creates the file and writes everything before the first row.
    bool open(const std::string& path, const ImageFileSpec& spec) {
        m_file = std::fopen(path.c_str(), "wb");
        if (m_file == nullptr) {
            m_error = "cannot create \"" + path + "\"";
            return false;
        }
        m_png = png_create_write_struct(PNG_LIBPNG_VER_STRING, this, &PngWriter::on_error,
                                        &PngWriter::on_warning);
        if (m_png != nullptr) m_info = png_create_info_struct(m_png);
        if (m_png == nullptr || m_info == nullptr) {
            m_error = "libpng could not allocate its state";
            return false;
        }
        // The text chunks' strings live until png_set_text has copied them.
        std::vector<png_text> texts;
        int level = -1, filter = -1;
        for (const ImageAttribute& a : spec.attributes) {
            if (a.kind == ImageAttribute::Kind::Integer && a.name == "png:compressionLevel")
                level = a.integer;
            if (a.kind == ImageAttribute::Kind::Integer && a.name == "png:filter")
                filter = a.integer;
            // A keyword is 1-79 Latin-1 bytes (png-spec, tEXt); longer ones would stop libpng.
            if (a.kind != ImageAttribute::Kind::Text || a.name.empty() || a.name.size() > 79 ||
                a.name.compare(0, 5, "oiio:") == 0)
                continue;
            png_text text{};
            text.compression = PNG_TEXT_COMPRESSION_NONE;
            text.key = const_cast<char*>(a.name.c_str());
            text.text = const_cast<char*>(a.text.c_str());
            text.text_length = a.text.size();
            texts.push_back(text);
        }
        const int bit_depth = spec.type == PixelType::UInt16 ? 16 : 8;
        return write_header(spec.channels, bit_depth, level, filter, texts.data(),
                            static_cast<int>(texts.size()));
    }

    bool write_image(PixelType type, const void* pixels) override {
        if (!same_type(type) || !starts_at(0)) return false;
        return write_rows(0, m_height, static_cast<const unsigned char*>(pixels));
    }

    bool write_tiles(int, int, int, int, const float*) override {
        m_error = "a PNG file has no tiles";
        return false;
    }

    bool write_scanlines(int y0, int y1, PixelType type, const void* pixels) override {
        if (!same_type(type) || !starts_at(y0)) return false;
        if (y1 < y0 || y1 > m_height) {
            m_error = "rows " + std::to_string(y0) + " to " + std::to_string(y1) +
                      " are outside the image's " + std::to_string(m_height);
            return false;
        }
        return write_rows(y0, y1, static_cast<const unsigned char*>(pixels));
    }

    bool close() override {
        if (m_file == nullptr) return m_error.empty();
        bool ok = m_error.empty();
        if (ok && m_next_row != m_height) {
            m_error = "only " + std::to_string(m_next_row) + " of the image's " +
                      std::to_string(m_height) + " rows were written";
            ok = false;
        }
        if (ok) ok = write_end();
        errno = 0;
        const bool flushed = std::fflush(m_file) == 0 && !std::ferror(m_file);
        const int flush_errno = errno;
        const bool closed = std::fclose(m_file) == 0;
        m_file = nullptr;
        if (ok && !(flushed && closed)) {
            m_error = "cannot write the file";
            errno = flush_errno != 0 ? flush_errno : errno;
            ok = false;
        }
        return ok;
    }

    std::string error() override { return m_error; }

  private:
    [[noreturn]] static void on_error(png_structp png, png_const_charp message) {
        static_cast<PngWriter*>(png_get_error_ptr(png))->m_error = message;
        png_longjmp(png, 1);
    }
    static void on_warning(png_structp, png_const_charp) {}

    bool same_type(PixelType type) {
        if (type == m_type) return true;
        m_error = std::string("pixels given as ") + type_name(type) + ", the file holds " +
                  type_name(m_type) + " values";
        return false;
    }
    bool starts_at(int y0) {
        if (!m_error.empty()) return false;  // a failed libpng call leaves its state undefined
        if (y0 == m_next_row) return true;
        m_error = "rows are written in order: row " + std::to_string(m_next_row) +
                  " is next, not row " + std::to_string(y0);
        return false;
    }

    bool write_header(int channels, int bit_depth, int level, int filter, png_text* texts,
                      int text_count) {
        if (setjmp(png_jmpbuf(m_png))) return false;
        png_init_io(m_png, m_file);
        // PNG allows sides up to 2^31 - 1; libpng's default limit is 10^6.
        png_set_user_limits(m_png, 0x7fffffff, 0x7fffffff);
        if (level >= 0) png_set_compression_level(m_png, level);
        if (filter >= 0) png_set_filter(m_png, PNG_FILTER_TYPE_BASE, filter);
        png_set_IHDR(m_png, m_info, static_cast<png_uint_32>(m_width),
                     static_cast<png_uint_32>(m_height), bit_depth, png_colour_type(channels),
                     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
        png_set_oFFs(m_png, m_info, 0, 0, PNG_OFFSET_PIXEL);
        if (text_count > 0) png_set_text(m_png, m_info, texts, text_count);
        png_write_info(m_png, m_info);
        // PNG stores 16-bit samples big-endian; the pixels given are the machine's.
        if (bit_depth == 16 && !is_big_endian()) png_set_swap(m_png);
        return true;
    }

    bool write_rows(int y0, int y1, const unsigned char* pixels) {
        if (setjmp(png_jmpbuf(m_png))) return false;
        for (int y = y0; y < y1; ++y) {
            png_write_row(m_png, pixels + static_cast<size_t>(y - y0) * m_row_bytes);
        }
        m_next_row = y1;
        return true;
    }

    bool write_end() {
        if (setjmp(png_jmpbuf(m_png))) return false;
        png_write_end(m_png, m_info);
        return true;
    }

    static bool is_big_endian() {
        const uint16_t one = 1;
        unsigned char first = 0;
        std::memcpy(&first, &one, 1);
        return first == 0;
    }

    int m_width, m_height;
    PixelType m_type;
    size_t m_row_bytes;
    std::FILE* m_file = nullptr;
    png_structp m_png = nullptr;
    png_infop m_info = nullptr;
    int m_next_row = 0;
    std::string m_error;
};

}  // namespace

std::unique_ptr<ImageWriter> create_png_writer(const std::string& path, const ImageFileSpec& spec,
                                               std::string& error) {
    if (spec.channels < 1 || spec.channels > 4 ||
        (spec.type != PixelType::UInt8 && spec.type != PixelType::UInt16) || spec.width <= 0 ||
        spec.height <= 0 || spec.tile_size != 0) {
        error = "PNG holds untiled 8- or 16-bit images of 1 to 4 channels, not " +
                std::to_string(spec.width) + "x" + std::to_string(spec.height) + " of " +
                std::to_string(spec.channels) + " " + type_name(spec.type) + " channels" +
                (spec.tile_size != 0 ? " in tiles" : "");
        return nullptr;
    }
    auto writer = std::make_unique<PngWriter>(spec);
    errno = 0;
    if (!writer->open(path, spec)) {
        const int open_errno = errno;
        error = writer->error();
        writer.reset();
        errno = open_errno;
        return nullptr;
    }
    return writer;
}

}  // namespace rayo
