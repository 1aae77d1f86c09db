// `rayo render` streaming its output (core/image/tile_stream.h, docs/high-resolution.md): the
// streamed file holds the in-memory render's pixels for any thread count and tile size, large
// images stream by default, refusals come before the render, and Ctrl-C leaves nothing.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <csignal>
#include <cstring>
#include <string>
#include <vector>

#include "tests/cli/cli_fixture.h"

namespace {

using rayo_test::CommandResult;
using rayo_test::WatchedResult;

using rayo_test::kSceneNff;

// The pixels as stored in the file (half stays half, 8-bit stays 8-bit) and the spec.
struct Stored {
    OIIO::ImageSpec spec;
    std::vector<unsigned char> bytes;
};

class StreamCli : public rayo_test::CliFixture {
  protected:
    Stored read_stored(const std::string& name) const {
        Stored s;
        auto in = OIIO::ImageInput::open((m_dir / name).string());
        EXPECT_TRUE(in) << name << ": " << OIIO::geterror();
        if (!in) return s;
        s.spec = in->spec();
        s.bytes.resize(s.spec.image_bytes());
        EXPECT_TRUE(in->read_image(0, 0, 0, s.spec.nchannels, s.spec.format, s.bytes.data()));
        return s;
    }
};

TEST_F(StreamCli, StreamedRendersHoldTheInMemoryPixels) {
    write("scene.nff", kSceneNff);
    for (const std::string ext : {".exr", ".png"}) {
        const CommandResult memory =
            run("render scene.nff --no-stream --threads 2 -o memory" + ext);
        ASSERT_EQ(memory.exit_code, 0) << memory.output;
        EXPECT_EQ(memory.output.find("(streamed)"), std::string::npos) << memory.output;
        const Stored expected = read_stored("memory" + ext);
        for (const std::string threads : {"1", "2"}) {
            for (const std::string tile : {"16", "64"}) {
                const std::string label = ext + " threads " + threads + " tile " + tile;
                const CommandResult r = run("render scene.nff --stream --threads " + threads +
                                            " --tile-size " + tile + " -o streamed" + ext);
                ASSERT_EQ(r.exit_code, 0) << label << "\n" << r.output;
                EXPECT_NE(r.output.find("after the last tile (streamed)"), std::string::npos)
                    << r.output;
                const Stored got = read_stored("streamed" + ext);
                ASSERT_EQ(got.bytes.size(), expected.bytes.size()) << label;
                EXPECT_EQ(0, std::memcmp(got.bytes.data(), expected.bytes.data(), got.bytes.size()))
                    << label;
                EXPECT_EQ(got.spec.get_string_attribute("rayo:scene"),
                          expected.spec.get_string_attribute("rayo:scene"));
                EXPECT_EQ(got.spec.get_string_attribute("rayo:camera"),
                          expected.spec.get_string_attribute("rayo:camera"));
            }
        }
    }
    EXPECT_EQ(listing(), (std::set<std::string>{"scene.nff", "memory.exr", "memory.png",
                                                "streamed.exr", "streamed.png"}));
}

// --exr-compression reaches the file's header, streamed and in memory; the pixels of a lossless
// compression are those of the default (zip).
TEST_F(StreamCli, TheExrCompressionIsWrittenToTheHeader) {
    write("scene.nff", kSceneNff);
    const CommandResult zip = run("render scene.nff --no-stream -o zip.exr");
    ASSERT_EQ(zip.exit_code, 0) << zip.output;
    const Stored expected = read_stored("zip.exr");
    EXPECT_EQ(expected.spec.get_string_attribute("compression"), "zip");
    for (const std::string compression : {"none", "rle", "piz", "dwaa"}) {
        for (const std::string stream : {"--stream", "--no-stream"}) {
            const std::string label = compression + " " + stream;
            const CommandResult r = run("render scene.nff " + stream + " --exr-compression " +
                                        compression + " -o out.exr");
            ASSERT_EQ(r.exit_code, 0) << label << "\n" << r.output;
            const Stored got = read_stored("out.exr");
            EXPECT_EQ(got.spec.get_string_attribute("compression"), compression) << label;
            ASSERT_EQ(got.bytes.size(), expected.bytes.size()) << label;
            const bool same =
                std::memcmp(got.bytes.data(), expected.bytes.data(), got.bytes.size()) == 0;
            EXPECT_EQ(same, compression != "dwaa") << label;  // DWAA is lossy
        }
    }
}

TEST_F(StreamCli, ImagesAboveAMegapixelStreamByDefault) {
    write("scene.nff", kSceneNff);
    const CommandResult r = run("render scene.nff --width 1100 --height 1000 -o big.exr");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("(streamed)"), std::string::npos) << r.output;
    EXPECT_EQ(read_stored("big.exr").spec.tile_width, 64);  // a tiled EXR
    const CommandResult small = run("render scene.nff --width 1000 --height 1000 -o small.exr");
    ASSERT_EQ(small.exit_code, 0) << small.output;
    EXPECT_EQ(small.output.find("(streamed)"), std::string::npos) << small.output;
    EXPECT_EQ(read_stored("small.exr").spec.tile_width, 0);  // scanlines, as before
}

TEST_F(StreamCli, ImpossibleOutputsAreRefusedBeforeTheRender) {
    write("scene.nff", kSceneNff);
    const struct {
        std::string args, message;
    } cases[] = {
        {"--no-stream --width 16385 --height 16384 -o a.exr",
         "a.exr: an image of 16385x16384 (268451840 pixels) is too large for an in-memory film"},
        {"--range normalize --width 16385 --height 16384 -o a.png",
         "a.png: an image of 16385x16384 (268451840 pixels) is too large for an in-memory film "
         "(at most 268435456 pixels, 4 GiB), which --range normalize needs; use --range clamp, "
         "or write EXR"},
        {"--stream --range normalize -o a.png", "a.png: --range normalize needs the whole image"},
        {"--width 65501 --height 16 -o a.jpg",
         "a.jpg: cannot write 65501x16: the format stores at most 65500 pixels a side"},
    };
    for (const auto& c : cases) {
        std::vector<std::string> args{"render", "scene.nff"};
        std::istringstream words(c.args);
        for (std::string w; words >> w;) args.push_back(w);
        const WatchedResult r = run_watched(args, 30.0);
        EXPECT_EQ(r.exit_code, 1) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find("rayo: error: " + c.message), std::string::npos) << c.args << "\n"
                                                                                 << r.output;
        EXPECT_LT(r.peak_rss_kb, 400 * 1024) << c.args;  // nothing the size of the image
        EXPECT_EQ(listing(), std::set<std::string>{"scene.nff"}) << c.args;
    }
}

TEST_F(StreamCli, InterruptingAStreamedRenderLeavesNothing) {
    write("scene.nff", kSceneNff);
    bool sent = false;
    const WatchedResult r =
        run_watched({"render", "scene.nff", "--stream", "--width", "2000", "--height", "2000",
                     "--spp", "4", "--threads", "1", "--no-journal", "-o", "big.exr"},
                    120.0, [&](pid_t pid) {
                        // Once the temporary file exists, the stream is open and tiles are being
                        // written.
                        for (const std::string& name : listing()) {
                            if (name.rfind(".big.exr.tmp", 0) == 0) {
                                ::kill(pid, SIGINT);
                                sent = true;
                                return true;
                            }
                        }
                        return false;
                    });
    EXPECT_TRUE(sent) << r.output;
    EXPECT_EQ(r.shell_status, 130) << r.output;
    // --no-journal: no partial render to finish tiles for (tests/cli/resume_cli_test.cpp).
    EXPECT_EQ(r.output.find("finishing the tiles in flight"), std::string::npos) << r.output;
    EXPECT_EQ(listing(), std::set<std::string>{"scene.nff"});
}

}  // namespace
