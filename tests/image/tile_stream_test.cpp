// Tests of core/image/tile_stream: a file streamed tile by tile (any order, several threads, any
// tile size) holds the same pixels and metadata as write_image of the same film, for every
// format; failures leave no file; choose_streaming's refusals.
#include "core/image/tile_stream.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include "core/error.h"
#include "core/film.h"
#include "core/tile_grid.h"

namespace fs = std::filesystem;

namespace rayo {
namespace {

class TileStreamTest : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("rayo_tile_stream_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    std::string file(const std::string& name) const { return (m_dir / name).string(); }
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(m_dir)) names.push_back(e.path().filename());
        std::sort(names.begin(), names.end());
        return names;
    }
    fs::path m_dir;
};

// A film with values a display encoding must treat with care: above 1, negative, partial and
// zero alpha, a NaN; every pixel different.
Film test_film(int width, int height) {
    Film film(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float r = 0.013f * x, g = 0.021f * y - 0.2f, b = std::sin(0.1f * (x + 3 * y));
            const float alpha = (x + y) % 7 == 0 ? 0.0f : ((x * y) % 5 == 0 ? 0.37f : 1.0f);
            film.set(x, y, Vec3(r * alpha, g * alpha, 2.5f * b * alpha), alpha);
        }
    }
    film.set(3, 2, Vec3(std::numeric_limits<float>::quiet_NaN(), 0.5f, 0.5f));
    return film;
}

// The file's pixels as stored (no conversion: half stays half, 8-bit stays 8-bit), its spec.
struct Stored {
    OIIO::ImageSpec spec;
    std::vector<unsigned char> bytes;
};
Stored read_stored(const std::string& path) {
    Stored s;
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return s;
    s.spec = in->spec();
    s.bytes.resize(s.spec.image_bytes());
    EXPECT_TRUE(in->read_image(0, 0, 0, s.spec.nchannels, s.spec.format, s.bytes.data()))
        << in->geterror();
    return s;
}

// Streams `film` to `path` in tiles of `tile_size`, the tiles shuffled (or in row order) and
// delivered from `threads` threads at once.
void stream_film(const Film& film, const std::string& path, int tile_size, int threads,
                 const OutputOptions& options, bool shuffle = true) {
    const TileGrid grid(film.width(), film.height(), tile_size);
    auto stream = TileStream::open(path, film.width(), film.height(), tile_size, options);
    std::vector<int> order(grid.tile_count());
    std::iota(order.begin(), order.end(), 0);
    // A fixed shuffle (no RNG): stride through the tiles by a step prime to their count.
    std::vector<int> shuffled;
    for (size_t i = 0, at = 0; shuffle && i < order.size(); ++i, at = (at + 7) % order.size()) {
        while (std::find(shuffled.begin(), shuffled.end(), static_cast<int>(at)) != shuffled.end())
            at = (at + 1) % order.size();
        shuffled.push_back(static_cast<int>(at));
    }
    if (!shuffle) shuffled = order;
    stream->begin(grid);
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t) {
        workers.emplace_back([&, t] {
            std::vector<float> rgba;
            for (size_t i = t; i < shuffled.size(); i += threads) {
                const Tile tile = grid.tile(shuffled[i]);
                rgba.clear();
                for (int y = 0; y < tile.height; ++y) {
                    const float* row =
                        &film.rgba()[(static_cast<size_t>(tile.y0 + y) * film.width() + tile.x0) *
                                     4];
                    rgba.insert(rgba.end(), row, row + tile.width * 4);
                }
                stream->write_tile(tile, rgba.data());
            }
        });
    }
    for (std::thread& w : workers) w.join();
    stream->finish();
}

OutputOptions with_metadata() {
    OutputOptions options;
    options.metadata["rayo:scene"] = "test-scene.json";
    options.metadata["rayo:spp"] = "4";
    return options;
}

TEST_F(TileStreamTest, StreamedFilesHoldTheInMemoryWritersPixels) {
    const Film film = test_film(150, 97);  // neither side a multiple of any tile size
    for (const std::string ext : {".exr", ".png", ".tif", ".jpg"}) {
        for (const bool half : {false, true}) {
            if (half && ext != ".exr") continue;
            OutputOptions options = with_metadata();
            options.half_float_exr = half;
            const std::string memory = file("memory" + ext);
            write_image(film, memory, options);
            const Stored expected = read_stored(memory);
            for (const int tile_size : {16, 48, 64, 256}) {
                for (const int threads : {1, 3}) {
                    const std::string label = ext + (half ? " half" : "") + " tile " +
                                              std::to_string(tile_size) + " threads " +
                                              std::to_string(threads);
                    const std::string streamed = file("streamed" + ext);
                    stream_film(film, streamed, tile_size, threads, options);
                    const Stored got = read_stored(streamed);
                    ASSERT_EQ(got.bytes.size(), expected.bytes.size()) << label;
                    EXPECT_EQ(got.spec.format, expected.spec.format) << label;
                    EXPECT_EQ(got.spec.nchannels, expected.spec.nchannels) << label;
                    EXPECT_EQ(
                        0, std::memcmp(got.bytes.data(), expected.bytes.data(), got.bytes.size()))
                        << label;
                    for (const char* key : {"rayo:scene", "rayo:spp", "Software"}) {
                        EXPECT_EQ(got.spec.get_string_attribute(key),
                                  expected.spec.get_string_attribute(key))
                            << label << " " << key;
                    }
                    if (ext == ".exr") {
                        EXPECT_EQ(got.spec.tile_width, tile_size) << label;  // a tiled EXR
                        EXPECT_EQ(got.spec.get_string_attribute("compression"), "zip") << label;
                    }
                    fs::remove(streamed);
                }
            }
            fs::remove(memory);
        }
    }
    EXPECT_TRUE(listing().empty());
}

// Tiles delivered in row order faster than the writer compresses them queue up in runs of
// adjacent tiles, which the writer gathers into one write_tiles call each: the file still holds
// the in-memory writer's pixels, at tile sizes that do and do not divide the image.
TEST_F(TileStreamTest, RunsOfAdjacentTilesAreWrittenTogether) {
    const Film film = test_film(1000, 150);
    for (const bool half : {false, true}) {
        OutputOptions options;
        options.half_float_exr = half;
        write_image(film, file("memory.exr"), options);
        const Stored expected = read_stored(file("memory.exr"));
        for (const int tile_size : {16, 64}) {
            for (const int threads : {1, 2}) {
                const std::string label = std::string(half ? "half" : "float") + " tile " +
                                          std::to_string(tile_size) + " threads " +
                                          std::to_string(threads);
                stream_film(film, file("streamed.exr"), tile_size, threads, options, false);
                const Stored got = read_stored(file("streamed.exr"));
                ASSERT_EQ(got.bytes.size(), expected.bytes.size()) << label;
                EXPECT_EQ(0, std::memcmp(got.bytes.data(), expected.bytes.data(), got.bytes.size()))
                    << label;
            }
        }
    }
}

// The compression of OutputOptions is the one in the header, streamed or not; the lossless ones
// keep the pixels; an unknown one is refused before a file is made.
TEST_F(TileStreamTest, TheExrCompressionIsTheOneAskedFor) {
    const Film film = test_film(150, 97);
    write_image(film, file("zip.exr"), OutputOptions());
    const Stored expected = read_stored(file("zip.exr"));
    EXPECT_EQ(expected.spec.get_string_attribute("compression"), "zip");
    for (const std::string compression : {"none", "rle", "zips", "zip", "piz"}) {
        OutputOptions options;
        options.exr_compression = compression;
        write_image(film, file("memory.exr"), options);
        stream_film(film, file("streamed.exr"), 32, 2, options);
        for (const std::string name : {"memory.exr", "streamed.exr"}) {
            const Stored got = read_stored(file(name));
            EXPECT_EQ(got.spec.get_string_attribute("compression"), compression) << name;
            ASSERT_EQ(got.bytes.size(), expected.bytes.size()) << compression << " " << name;
            EXPECT_EQ(0, std::memcmp(got.bytes.data(), expected.bytes.data(), got.bytes.size()))
                << compression << " " << name;
        }
    }
    OutputOptions unknown;
    unknown.exr_compression = "zstd";
    fs::remove_all(m_dir);
    fs::create_directories(m_dir);
    EXPECT_THROW(write_image(film, file("a.exr"), unknown), InputError);
    EXPECT_THROW(TileStream::open(file("a.exr"), 64, 64, 16, unknown), InputError);
    EXPECT_TRUE(listing().empty());
}

TEST_F(TileStreamTest, AStreamNotFinishedLeavesNoFile) {
    const Film film = test_film(64, 64);
    for (const std::string name : {"a.exr", "a.png"}) {
        {
            auto stream = TileStream::open(file(name), 64, 64, 16, OutputOptions());
            const TileGrid grid(64, 64, 16);
            stream->begin(grid);
            std::vector<float> rgba(16 * 16 * 4, 0.5f);
            stream->write_tile(grid.tile(0), rgba.data());
            EXPECT_FALSE(listing().empty());  // the temporary exists while the stream does
        }
        EXPECT_TRUE(listing().empty()) << name;
    }
}

TEST_F(TileStreamTest, AStreamMissingTilesIsNotCommitted) {
    auto stream = TileStream::open(file("a.png"), 64, 64, 16, OutputOptions());
    const TileGrid grid(64, 64, 16);
    stream->begin(grid);
    std::vector<float> rgba(16 * 16 * 4, 0.5f);
    stream->write_tile(grid.tile(0), rgba.data());
    EXPECT_THROW(stream->finish(), InputError);
    stream.reset();
    EXPECT_TRUE(listing().empty());
}

TEST_F(TileStreamTest, AnUnwritableDirectoryIsReportedAtOpen) {
    try {
        TileStream::open(file("missing/a.exr"), 64, 64, 16, OutputOptions());
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("missing/a.exr: cannot write"), std::string::npos)
            << e.what();
    }
    EXPECT_TRUE(listing().empty());
}

TEST_F(TileStreamTest, ChoiceOfStreaming) {
    const OutputOptions clamp;
    OutputOptions normalize;
    normalize.range = RangeMode::Normalize;
    EXPECT_FALSE(choose_streaming("a.exr", 1024, 1024, clamp, StreamMode::Auto));
    EXPECT_TRUE(choose_streaming("a.exr", 1025, 1024, clamp, StreamMode::Auto));
    EXPECT_TRUE(choose_streaming("a.png", 64, 64, clamp, StreamMode::Always));
    EXPECT_FALSE(choose_streaming("a.png", 4096, 4096, clamp, StreamMode::Never));
    EXPECT_TRUE(choose_streaming("a.exr", 65536, 65536, clamp, StreamMode::Auto));
    // normalize: in memory while it fits; EXR ignores the range mode and streams.
    EXPECT_FALSE(choose_streaming("a.png", 4096, 4096, normalize, StreamMode::Auto));
    EXPECT_TRUE(choose_streaming("a.exr", 4096, 4096, normalize, StreamMode::Auto));
    EXPECT_THROW(choose_streaming("a.png", 64, 64, normalize, StreamMode::Always), InputError);
    EXPECT_THROW(choose_streaming("a.png", 16385, 16384, normalize, StreamMode::Auto), InputError);
    EXPECT_THROW(choose_streaming("a.exr", 16385, 16384, clamp, StreamMode::Never), InputError);
    // JPEG stores at most 65500 a side.
    EXPECT_TRUE(choose_streaming("a.jpg", 65500, 100, clamp, StreamMode::Auto));
    EXPECT_THROW(choose_streaming("a.jpg", 65501, 100, clamp, StreamMode::Auto), InputError);
}

}  // namespace
}  // namespace rayo
