// Tests of core/image/image_writers (docs/performance.md "Writing PNG and EXR without
// OpenImageIO"): the direct writers, libpng's and OpenEXR's, write the pixels and metadata the
// reference writer, OpenImageIO's (the image module), writes, in memory and streamed, for 8- and
// 16-bit PNG and for half and float EXR under every compression; both files are read back with
// OpenImageIO. Then the direct writers' failures: a missing directory, a full disk, rows or
// tiles missing or out of order.
#include "core/image/image_writers.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/film.h"
#include "core/image/exr_writer.h"
#include "core/image/png_writer.h"
#include "core/image/tile_stream.h"
#include "core/tile_grid.h"

namespace fs = std::filesystem;

namespace rayo {
namespace {

class ImageWritersTest : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("rayo_image_writers_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

  public:
    std::string file(const std::string& name) const { return (m_dir / name).string(); }

  protected:
    size_t file_count() const {
        return static_cast<size_t>(std::distance(fs::directory_iterator(m_dir), {}));
    }
    fs::path m_dir;
};

// Values above 1, negative, partial and zero alpha, a NaN, every pixel different; 37 × 29 so
// that tiles of 16 leave partial tiles on the right and at the bottom.
Film test_film(int width = 37, int height = 29) {
    Film film(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float r = 0.0137f * x + 1e-4f * y, g = 0.0211f * y - 0.2f;
            const float b = 3.0f * std::sin(0.1f * (x + 3 * y));
            const float alpha = (x + y) % 7 == 0 ? 0.0f : ((x * y) % 5 == 0 ? 0.37f : 1.0f);
            film.set(x, y, Vec3(r * alpha, g * alpha, b * alpha), alpha);
        }
    }
    film.set(3, 2, Vec3(std::numeric_limits<float>::quiet_NaN(), 0.5f, 65504.0f * 4));
    return film;
}

// The file's pixels as stored (half stays half, 8-bit stays 8-bit, colour not multiplied by
// alpha) and its spec, read with OpenImageIO.
struct Stored {
    OIIO::ImageSpec spec;
    std::vector<unsigned char> bytes;
};
Stored read_stored(const std::string& path) {
    Stored s;
    // Alpha as stored: OpenImageIO would premultiply a PNG's colour by it.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
    if (!in) return s;
    s.spec = in->spec();
    s.bytes.resize(s.spec.image_bytes());
    EXPECT_TRUE(in->read_image(0, 0, 0, s.spec.nchannels, s.spec.format, s.bytes.data()))
        << in->geterror();
    return s;
}

// Streams `film` to `path` in tiles of 16, in row order from one thread.
void stream_film(const Film& film, const std::string& path, const OutputOptions& options) {
    const TileGrid grid(film.width(), film.height(), 16);
    auto stream = TileStream::open(path, film.width(), film.height(), 16, options);
    stream->begin(grid);
    std::vector<float> rgba;
    for (int i = 0; i < grid.tile_count(); ++i) {
        const Tile tile = grid.tile(i);
        rgba.clear();
        for (int y = 0; y < tile.height; ++y) {
            const float* row =
                &film.rgba()[(static_cast<size_t>(tile.y0 + y) * film.width() + tile.x0) * 4];
            rgba.insert(rgba.end(), row, row + tile.width * 4);
        }
        stream->write_tile(tile, rgba.data());
    }
    stream->finish();
}

// Writes `film` to `name` with each writer (in memory, or streamed) and expects the same stored
// pixels, the same layout and the same metadata, rayo's and the format's (`attributes`).
void expect_same_files(const ImageWritersTest& test, const Film& film, const std::string& name,
                       OutputOptions options, bool streamed,
                       const std::vector<std::string>& attributes) {
    const std::string direct = test.file("direct-" + name), oiio = test.file("oiio-" + name);
    options.metadata["rayo:scene"] = "a scene.json";
    options.metadata["rayo:spp"] = "4";
    for (const auto& [path, choice] :
         {std::pair{direct, ImageWriterChoice::Direct}, {oiio, ImageWriterChoice::OpenImageIO}}) {
        options.writer = choice;
        if (streamed) {
            stream_film(film, path, options);
        } else {
            write_image(film, path, options);
        }
    }
    const Stored a = read_stored(direct), b = read_stored(oiio);
    const std::string what = name + (streamed ? " streamed" : " in memory");
    ASSERT_EQ(a.spec.format, b.spec.format) << what;
    ASSERT_EQ(a.spec.nchannels, b.spec.nchannels) << what;
    EXPECT_EQ(a.spec.width, film.width()) << what;
    EXPECT_EQ(a.spec.height, film.height()) << what;
    EXPECT_EQ(a.spec.tile_width, b.spec.tile_width) << what;
    EXPECT_EQ(a.spec.tile_height, b.spec.tile_height) << what;
    EXPECT_EQ(a.spec.channelnames, b.spec.channelnames) << what;
    ASSERT_EQ(a.bytes.size(), b.bytes.size()) << what;
    EXPECT_TRUE(a.bytes == b.bytes) << what << ": the pixels differ";
    for (const std::string& attribute : {"Software", "rayo:scene", "rayo:spp"}) {
        EXPECT_EQ(a.spec.get_string_attribute(attribute), b.spec.get_string_attribute(attribute))
            << what << " " << attribute;
        EXPECT_NE(a.spec.get_string_attribute(attribute), "") << what << " " << attribute;
    }
    for (const std::string& attribute : attributes) {
        const OIIO::ParamValue* x = a.spec.find_attribute(attribute);
        const OIIO::ParamValue* y = b.spec.find_attribute(attribute);
        ASSERT_TRUE(x != nullptr && y != nullptr) << what << " " << attribute;
        EXPECT_EQ(x->type(), y->type()) << what << " " << attribute;
        EXPECT_EQ(a.spec.metadata_val(*x), b.spec.metadata_val(*y)) << what << " " << attribute;
    }
}

TEST_F(ImageWritersTest, PngInMemoryAndStreamedMatchesOpenImageIOs) {
    const Film film = test_film();
    for (const bool streamed : {false, true}) {
        expect_same_files(*this, film, streamed ? "s.png" : "m.png", OutputOptions{}, streamed, {});
    }
    EXPECT_EQ(read_stored(file("direct-m.png")).spec.format, OIIO::TypeDesc::UINT8);
}

TEST_F(ImageWritersTest, ExrOfEveryCompressionHalfAndFloatMatchesOpenImageIOs) {
    const Film film = test_film();
    for (const std::string& compression : exr_compression_list()) {
        for (const bool half : {false, true}) {
            for (const bool streamed : {false, true}) {
                OutputOptions options;
                options.exr_compression = compression;
                options.half_float_exr = half;
                const std::string name =
                    compression + (half ? "-half" : "-float") + (streamed ? "-s" : "-m") + ".exr";
                expect_same_files(
                    *this, film, name, options, streamed,
                    {"compression", "chromaticities", "PixelAspectRatio", "screenWindowWidth"});
                EXPECT_EQ(read_stored(file("direct-" + name)).spec.format,
                          half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT)
                    << name;
            }
        }
    }
}

TEST_F(ImageWritersTest, ExrFloatsAreTheFilmsBits) {
    const Film film = test_film();
    write_image(film, file("f.exr"), OutputOptions{});
    const Stored s = read_stored(file("f.exr"));
    ASSERT_EQ(s.spec.format, OIIO::TypeDesc::FLOAT);
    ASSERT_EQ(s.bytes.size(), film.rgba().size() * sizeof(float));
    EXPECT_EQ(std::memcmp(s.bytes.data(), film.rgba().data(), s.bytes.size()), 0);
}

// rayo writes PNG in 8 bits; the direct writer also takes 16 bits and 1 to 4 channels, as
// OpenImageIO's does: each written whole and in bands of rows, against OpenImageIO's file.
TEST_F(ImageWritersTest, PngOfEveryDepthAndChannelCountMatchesOpenImageIOs) {
    const int width = 23, height = 17;
    for (const PixelType type : {PixelType::UInt8, PixelType::UInt16}) {
        for (int channels = 1; channels <= 4; ++channels) {
            const int bytes = type == PixelType::UInt16 ? 2 : 1;
            std::vector<unsigned char> pixels(static_cast<size_t>(width) * height * channels *
                                              bytes);
            for (size_t i = 0; i < pixels.size(); ++i)
                pixels[i] = static_cast<unsigned char>(i * 37 + i / 5);
            ImageFileSpec spec;
            spec.width = width;
            spec.height = height;
            spec.channels = channels;
            spec.type = type;
            spec.add("Software", "rayo test");
            spec.add("png:compressionLevel", 1);
            spec.add("oiio:UnassociatedAlpha", 1);  // as rayo's spec says (output_encoding.h)
            const std::string name = std::to_string(bytes * 8) + "-" + std::to_string(channels);
            const std::string whole = file(name + "-whole.png"), bands = file(name + "-bands.png"),
                              oiio = file(name + "-oiio.png");
            std::string error;
            auto a = create_image_writer(whole, spec, ImageWriterChoice::Direct, error);
            ASSERT_TRUE(a) << error;
            ASSERT_TRUE(a->write_image(type, pixels.data())) << a->error();
            ASSERT_TRUE(a->close()) << a->error();
            auto b = create_image_writer(bands, spec, ImageWriterChoice::Direct, error);
            ASSERT_TRUE(b) << error;
            const size_t row_bytes = static_cast<size_t>(width) * channels * bytes;
            for (int y0 = 0; y0 < height; y0 += 5) {
                const int y1 = std::min(height, y0 + 5);
                ASSERT_TRUE(b->write_scanlines(y0, y1, type, &pixels[y0 * row_bytes]))
                    << b->error();
            }
            ASSERT_TRUE(b->close()) << b->error();
            auto c = create_image_writer(oiio, spec, ImageWriterChoice::OpenImageIO, error);
            ASSERT_TRUE(c) << error;
            ASSERT_TRUE(c->write_image(type, pixels.data())) << c->error();
            ASSERT_TRUE(c->close()) << c->error();
            const Stored x = read_stored(whole), y = read_stored(bands), z = read_stored(oiio);
            EXPECT_EQ(x.spec.nchannels, channels) << name;
            EXPECT_EQ(x.spec.format, z.spec.format) << name;
            EXPECT_TRUE(x.bytes == pixels) << name << ": not the pixels written";
            EXPECT_TRUE(y.bytes == pixels) << name << ": bands differ";
            EXPECT_TRUE(z.bytes == pixels) << name << ": OpenImageIO's differ";
            EXPECT_EQ(x.spec.get_string_attribute("Software"), "rayo test") << name;
        }
    }
}

TEST_F(ImageWritersTest, OnlyTiffJpegAndTheReferenceWriterNeedTheImageModule) {
    EXPECT_FALSE(writer_needs_image_library("a.png", ImageWriterChoice::Direct));
    EXPECT_FALSE(writer_needs_image_library("a.EXR", ImageWriterChoice::Direct));
    EXPECT_TRUE(writer_needs_image_library("a.tif", ImageWriterChoice::Direct));
    EXPECT_TRUE(writer_needs_image_library("a.jpg", ImageWriterChoice::Direct));
    EXPECT_TRUE(writer_needs_image_library("a.png", ImageWriterChoice::OpenImageIO));
    EXPECT_TRUE(writer_needs_image_library("a.exr", ImageWriterChoice::OpenImageIO));
    EXPECT_THROW(writer_needs_image_library("a.bmp", ImageWriterChoice::Direct), InputError);
}

// A directory that is gone: the same error as the reference writer's, with the system's reason,
// and nothing left behind.
TEST_F(ImageWritersTest, AMissingDirectoryIsAnErrorWithTheSystemsReason) {
    const Film film = test_film(8, 8);
    for (const std::string name : {"gone/a.png", "gone/a.exr"}) {
        for (const bool streamed : {false, true}) {
            OutputOptions options;
            try {
                if (streamed) {
                    stream_film(film, file(name), options);
                } else {
                    write_image(film, file(name), options);
                }
                ADD_FAILURE() << name << " written";
            } catch (const InputError& e) {
                const std::string message = e.what();
                EXPECT_NE(message.find(file(name)), std::string::npos) << message;
                EXPECT_NE(message.find("cannot"), std::string::npos) << message;
                EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
            }
            EXPECT_EQ(file_count(), 0u) << name;
        }
    }
}

// /dev/full takes the open and fails every write with ENOSPC: the writer says so when the data
// reaches it, at the latest at close().
TEST_F(ImageWritersTest, AFullDiskIsAnError) {
    const Film film = test_film(64, 64);
    ImageFileSpec png;
    png.width = png.height = 64;
    png.channels = 4;
    png.type = PixelType::UInt8;
    const std::vector<unsigned char> bytes(64 * 64 * 4, 7);
    std::string error;
    auto p = create_png_writer("/dev/full", png, error);
    ASSERT_TRUE(p) << error;
    const bool written = p->write_image(PixelType::UInt8, bytes.data());
    EXPECT_FALSE(written && p->close());
    EXPECT_NE(p->error(), "");

    ImageFileSpec exr = png;
    exr.type = PixelType::Float;
    exr.add("compression", "none");
    auto e = create_exr_writer("/dev/full", exr, error);
    if (e) {
        const bool ok = e->write_image(PixelType::Float, film.rgba().data());
        EXPECT_FALSE(ok && e->close());
        EXPECT_NE(e->error(), "");
    } else {
        EXPECT_NE(error, "");
    }
}

TEST_F(ImageWritersTest, RowsAndTilesMissingOrOutOfOrderAreErrors) {
    ImageFileSpec png;
    png.width = 10;
    png.height = 20;
    png.channels = 4;
    png.type = PixelType::UInt8;
    const std::vector<unsigned char> bytes(10 * 20 * 4, 200);
    std::string error;
    auto p = create_png_writer(file("rows.png"), png, error);
    ASSERT_TRUE(p) << error;
    EXPECT_FALSE(p->write_scanlines(5, 10, PixelType::UInt8, bytes.data()));
    EXPECT_NE(p->error().find("row 0 is next"), std::string::npos) << p->error();
    auto q = create_png_writer(file("half.png"), png, error);
    ASSERT_TRUE(q) << error;
    ASSERT_TRUE(q->write_scanlines(0, 10, PixelType::UInt8, bytes.data())) << q->error();
    EXPECT_FALSE(q->close());
    EXPECT_NE(q->error().find("only 10 of the image's 20 rows"), std::string::npos) << q->error();
    EXPECT_FALSE(q->write_tiles(0, 1, 0, 1, nullptr));

    ImageFileSpec exr;
    exr.width = 40;
    exr.height = 20;
    exr.channels = 4;
    exr.type = PixelType::Half;
    exr.tile_size = 16;
    const std::vector<float> tile(16 * 16 * 4, 0.5f);
    auto t = create_exr_writer(file("tiles.exr"), exr, error);
    ASSERT_TRUE(t) << error;
    EXPECT_FALSE(t->write_tiles(8, 24, 0, 16, tile.data()));  // off the tile grid
    auto u = create_exr_writer(file("some.exr"), exr, error);
    ASSERT_TRUE(u) << error;
    ASSERT_TRUE(u->write_tiles(16, 32, 0, 16, tile.data())) << u->error();
    EXPECT_FALSE(u->close());
    EXPECT_NE(u->error().find("5 tiles were not written"), std::string::npos) << u->error();
}

TEST_F(ImageWritersTest, SpecsTheFormatCannotHoldAreRefused) {
    ImageFileSpec spec;
    spec.width = spec.height = 4;
    spec.channels = 4;
    spec.type = PixelType::Float;
    std::string error;
    EXPECT_FALSE(create_png_writer(file("f.png"), spec, error));
    EXPECT_NE(error.find("PNG holds"), std::string::npos) << error;
    spec.type = PixelType::UInt8;
    EXPECT_FALSE(create_exr_writer(file("b.exr"), spec, error));
    EXPECT_NE(error.find("half or float"), std::string::npos) << error;
    spec.type = PixelType::Float;
    spec.add("compression", "lzma");
    EXPECT_FALSE(create_exr_writer(file("c.exr"), spec, error));
    EXPECT_NE(error.find("unknown EXR compression 'lzma'"), std::string::npos) << error;
}

}  // namespace
}  // namespace rayo
