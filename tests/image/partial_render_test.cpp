// Tests of core/image/partial_render: recorded tiles come back bit for bit (every float value,
// NaN and infinities included) in tile order, in any grid; a slot that does not check out is
// missing; the file exists only while it holds a tile; the fingerprint is compared entry by
// entry. The end-to-end cases (signals, --resume, kill -9) are tests/cli/resume_cli_test.cpp.
#include "core/image/partial_render.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "core/error.h"
#include "core/film.h"

namespace fs = std::filesystem;

namespace rayo {
namespace {

class PartialRenderTest : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("rayo_partial_render_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
        m_output = (m_dir / "out.exr").string();
    }
    void TearDown() override { fs::remove_all(m_dir); }

    // Tile `index` of `grid` with values that no arithmetic would produce by chance: every bit
    // pattern class (negative zero, denormals, NaN with a payload, infinities, large values).
    static std::vector<float> tile_pixels(const TileGrid& grid, int index) {
        const Tile tile = grid.tile(index);
        std::vector<float> rgba(tile.pixel_count() * 4);
        for (size_t i = 0; i < rgba.size(); ++i) {
            uint32_t bits = static_cast<uint32_t>(index * 2654435761u + i * 40503u);
            if (i % 97 == 0) bits = 0x7fc01234u;  // NaN with a payload
            if (i % 89 == 0) bits = 0xff800000u;  // -inf
            if (i % 83 == 0) bits = 0x80000000u;  // -0
            std::memcpy(&rgba[i], &bits, 4);
        }
        return rgba;
    }

    static std::vector<uint32_t> bits_of(const std::vector<float>& values) {
        std::vector<uint32_t> bits(values.size());
        std::memcpy(bits.data(), values.data(), values.size() * 4);
        return bits;
    }

    // A run of a new partial render that records `indices` of `grid` and ends; tiles are kept
    // from `keep_after` on.
    void record_tiles(const TileGrid& grid, const std::vector<int>& indices,
                      std::chrono::steady_clock::duration keep_after =
                          std::chrono::steady_clock::duration(0)) const {
        auto partial = PartialRender::create(m_output, grid, m_fingerprint, keep_after);
        Film sink(grid.image_width(), grid.image_height());
        auto recorder = partial->recording_sink(sink);
        recorder->begin(grid);
        for (const int index : indices)
            recorder->write_tile(grid.tile(index), tile_pixels(grid, index).data());
    }

    fs::path m_dir;
    std::string m_output;
    const RenderFingerprint m_fingerprint{
        {"scene contents", "12 bytes, checksum 1f"}, {"resolution", "100x70"}, {"spp", "1"}};
};

// Records some tiles, then resumes: the missing tiles are the others, and the recorded ones
// reach a film bit for bit, before any new tile, in tile order.
TEST_F(PartialRenderTest, RecordedTilesComeBackBitForBit) {
    const TileGrid grid(100, 70, 32);  // 4 × 3 tiles, narrower at the right and bottom
    const std::vector<int> recorded = {5, 0, 11, 3, 7};
    {
        auto partial = PartialRender::create(m_output, grid, m_fingerprint);
        Film sink(100, 70);
        auto recorder = partial->recording_sink(sink);
        recorder->begin(grid);
        EXPECT_FALSE(fs::exists(partial_render_path(m_output))) << "created before a tile";
        for (const int index : recorded)
            recorder->write_tile(grid.tile(index), tile_pixels(grid, index).data());
        partial->flush();
        EXPECT_EQ(partial->tiles_done(), 5);
        EXPECT_TRUE(partial->failure().empty());
    }
    ASSERT_TRUE(fs::exists(partial_render_path(m_output)));

    auto partial = PartialRender::resume(m_output, grid, m_fingerprint);
    EXPECT_EQ(partial->tiles_done(), 5);
    EXPECT_EQ(partial->missing_tiles(), (std::vector<int>{1, 2, 4, 6, 8, 9, 10}));
    // A sink that notes the order and the pixels it is given.
    struct Collect : TileSink {
        std::vector<int> order;
        std::vector<std::vector<float>> pixels;
        void write_tile(const Tile& tile, const float* rgba) override {
            order.push_back(tile.index);
            pixels.emplace_back(rgba, rgba + tile.pixel_count() * 4);
        }
    } collect;
    auto recorder = partial->recording_sink(collect);
    recorder->begin(grid);
    EXPECT_EQ(collect.order, (std::vector<int>{0, 3, 5, 7, 11}));
    for (size_t i = 0; i < collect.order.size(); ++i) {
        EXPECT_EQ(bits_of(collect.pixels[i]), bits_of(tile_pixels(grid, collect.order[i])))
            << "tile " << collect.order[i];
    }
    partial->remove();
    EXPECT_FALSE(fs::exists(partial_render_path(m_output)));
}

// While a render writes its partial render (the lock on the file, held until the process ends),
// a second render of the same output is refused, as a start and as a resume, with a message
// that says so; once the first has ended the partial render resumes.
TEST_F(PartialRenderTest, ASecondRenderOfTheSameOutputIsRefusedWhileTheFirstRuns) {
    const TileGrid grid(64, 64, 16);
    {
        auto running = PartialRender::create(m_output, grid, m_fingerprint);
        Film sink(64, 64);
        auto recorder = running->recording_sink(sink);
        recorder->begin(grid);
        recorder->write_tile(grid.tile(2), tile_pixels(grid, 2).data());
        running->flush();
        ASSERT_TRUE(running->failure().empty()) << running->failure();
        for (const bool resume : {false, true}) {
            try {
                if (resume)
                    PartialRender::resume(m_output, grid, m_fingerprint);
                else
                    PartialRender::create(m_output, grid, m_fingerprint);
                ADD_FAILURE() << (resume ? "resume" : "create") << " was not refused";
            } catch (const InputError& error) {
                EXPECT_NE(std::string(error.what()).find("is running now"), std::string::npos)
                    << error.what();
            }
        }
        EXPECT_EQ(running->tiles_done(), 1) << "the refused runs touched the file";
    }
    auto partial = PartialRender::resume(m_output, grid, m_fingerprint);
    EXPECT_EQ(partial->tiles_done(), 1);
}

// A slot whose bytes do not match its checksum (torn, or another tile's) does not count.
TEST_F(PartialRenderTest, SlotsThatDoNotCheckOutAreMissing) {
    const TileGrid grid(64, 64, 16);
    record_tiles(grid, {0, 1, 2, 3});
    const std::string path = partial_render_path(m_output);
    const size_t slot = 32 + 16 * 16 * 16;
    // Tile 2's last pixel byte flipped; tile 3 cut short by one byte.
    {
        std::FILE* file = std::fopen(path.c_str(), "r+b");
        ASSERT_NE(file, nullptr);
        ASSERT_EQ(std::fseek(file, static_cast<long>(4096 + 3 * slot - 1), SEEK_SET), 0);
        const int byte = std::fgetc(file);
        ASSERT_EQ(std::fseek(file, static_cast<long>(4096 + 3 * slot - 1), SEEK_SET), 0);
        std::fputc(byte ^ 1, file);
        std::fclose(file);
    }
    fs::resize_file(path, 4096 + 4 * slot - 1);
    auto partial = PartialRender::resume(m_output, grid, m_fingerprint);
    EXPECT_EQ(partial->tiles_done(), 2);
    EXPECT_EQ(partial->missing_tiles().front(), 2);
    EXPECT_EQ(partial->missing_tiles().size(), 14u);
}

// No tile, no file: a run stopped before its first tile leaves nothing.
TEST_F(PartialRenderTest, NoTileNoFile) {
    const TileGrid grid(64, 64, 16);
    record_tiles(grid, {});
    EXPECT_TRUE(fs::is_empty(m_dir));
}

// Tiles that finish before the partial render's keep_after (rayo render --journal-after) are
// not kept: a render shorter than that leaves no file. The sink still receives every tile.
TEST_F(PartialRenderTest, TilesBeforeKeepAfterAreNotKept) {
    const TileGrid grid(64, 64, 16);
    record_tiles(grid, {0, 1, 2}, std::chrono::hours(1));
    EXPECT_TRUE(fs::is_empty(m_dir));

    auto partial = PartialRender::create(m_output, grid, m_fingerprint, std::chrono::hours(1));
    Film sink(grid.image_width(), grid.image_height());
    auto recorder = partial->recording_sink(sink);
    recorder->begin(grid);
    const std::vector<float> pixels = tile_pixels(grid, 3);
    recorder->write_tile(grid.tile(3), pixels.data());
    partial->flush();
    EXPECT_EQ(partial->tiles_done(), 0);
    const Tile tile = grid.tile(3);
    EXPECT_EQ(bits_of({sink.rgb(tile.x0, tile.y0).x}), bits_of({pixels[0]}));
}

// A render that outlives the delay: the tiles before it are missing from the partial render,
// those after it are kept and come back on resume.
TEST_F(PartialRenderTest, TilesAfterKeepAfterAreKept) {
    const TileGrid grid(64, 64, 16);
    {
        auto partial =
            PartialRender::create(m_output, grid, m_fingerprint, std::chrono::seconds(1));
        Film sink(grid.image_width(), grid.image_height());
        auto recorder = partial->recording_sink(sink);
        recorder->begin(grid);
        recorder->write_tile(grid.tile(0), tile_pixels(grid, 0).data());
        std::this_thread::sleep_for(std::chrono::milliseconds(1100));
        recorder->write_tile(grid.tile(1), tile_pixels(grid, 1).data());
        partial->flush();
        EXPECT_EQ(partial->tiles_done(), 1);
    }
    auto resumed = PartialRender::resume(m_output, grid, m_fingerprint);
    EXPECT_EQ(resumed->tiles_done(), 1);
    const std::vector<int> missing = resumed->missing_tiles();
    ASSERT_FALSE(missing.empty());
    EXPECT_EQ(missing.front(), 0);
    EXPECT_EQ(std::count(missing.begin(), missing.end(), 1), 0);
}

// Every entry that differs is named, with both values; entries only one side has too.
TEST_F(PartialRenderTest, ResumeNamesEveryDifference) {
    const TileGrid grid(64, 64, 16);
    record_tiles(grid, {0});
    RenderFingerprint other = m_fingerprint;
    other[1].second = "100x71";
    other[2].second = "4";
    other.emplace_back("max depth", "5");
    try {
        PartialRender::resume(m_output, grid, other);
        FAIL() << "resumed with other settings";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("resolution: 100x70 in the partial render, 100x71 now"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("spp: 1 in the partial render, 4 now"), std::string::npos)
            << message;
        EXPECT_NE(message.find("max depth: (not recorded) in the partial render, 5 now"),
                  std::string::npos)
            << message;
        EXPECT_EQ(message.find("scene contents"), std::string::npos) << message;
    }
    EXPECT_TRUE(fs::exists(partial_render_path(m_output))) << "a refused resume keeps the file";
    EXPECT_THROW(PartialRender::create(m_output, grid, m_fingerprint), InputError);
}

// A file of that name that is not a partial render (or whose header claims an absurd size) is
// refused by name, and left alone.
TEST_F(PartialRenderTest, ForeignFilesAreRefused) {
    const TileGrid grid(64, 64, 16);
    for (const std::string& text :
         {std::string("hello\n"), std::string("rayo partial render 1 99999999999999999\n"),
          std::string("rayo partial render 1 4096\n")}) {
        std::FILE* file = std::fopen(partial_render_path(m_output).c_str(), "wb");
        ASSERT_NE(file, nullptr);
        std::fwrite(text.data(), 1, text.size(), file);
        std::fclose(file);
        try {
            PartialRender::resume(m_output, grid, m_fingerprint);
            FAIL() << text;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("--resume: '" + partial_render_path(m_output) +
                                                 "' is not a partial render of rayo"),
                      std::string::npos)
                << e.what();
        }
        EXPECT_EQ(fs::file_size(partial_render_path(m_output)), text.size());
    }
}

}  // namespace
}  // namespace rayo
