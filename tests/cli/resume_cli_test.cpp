// `rayo render` interrupted and resumed (core/image/partial_render.h, docs/high-resolution.md,
// "Interrupt and resume"): SIGINT/SIGTERM stop the hand-out of tiles, keep the finished ones in
// OUTPUT.rayo-partial and leave nothing under the output's name; `--resume` renders only the
// missing tiles, into the same bits as an uninterrupted render, and refuses other settings;
// records torn by kill -9 are rendered again. (`--no-journal`, which keeps nothing and ends at the
// first signal: tests/cli/stream_cli_test.cpp and bad_input_files_test.cpp.) The interruptions are
// deterministic: RAYO_TEST_INTERRUPT=K[:TERM] raises the signal on the worker that finishes the
// K-th tile, so with one thread and --journal-after 0 exactly K tiles are done.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/cli/cli_fixture.h"

namespace {

using rayo_test::CommandResult;
using rayo_test::WatchedResult;

using rayo_test::kSceneNff;
// kSceneNff is 150 × 100 pixels: 10 × 7 = 70 tiles of 16.
constexpr int kTiles = 70;
// The partial render's layout for this scene (core/image/partial_render.cpp): a 4096-byte
// header, then one slot per tile of 32 bytes of record header and 16² float RGBA pixels.
constexpr size_t kHeaderBytes = 4096;
constexpr size_t kSlotBytes = 32 + 16 * 16 * 16;

class ResumeCli : public rayo_test::CliFixture {
  protected:
    // The pixels as stored (8-bit PNG stays 8-bit), for a byte-for-byte comparison.
    std::vector<unsigned char> stored(const std::string& name) const {
        std::vector<unsigned char> bytes;
        auto in = OIIO::ImageInput::open((m_dir / name).string());
        EXPECT_TRUE(in) << name << ": " << OIIO::geterror();
        if (!in) return bytes;
        bytes.resize(in->spec().image_bytes());
        EXPECT_TRUE(in->read_image(0, 0, 0, in->spec().nchannels, in->spec().format, bytes.data()));
        return bytes;
    }

    // `rayo render scene.nff --tile-size 16 ARGS` interrupted after `tiles` tiles (one thread),
    // every tile kept (--journal-after 0; a resume keeps every tile anyway).
    CommandResult interrupted(const std::string& args, int tiles, const std::string& signal = "") {
        const bool resume = args.find("--resume") != std::string::npos;
        return run("render scene.nff --tile-size 16 --threads 1 " +
                       std::string(resume ? "" : "--journal-after 0 ") + args,
                   "RAYO_TEST_INTERRUPT=" + std::to_string(tiles) + signal);
    }

    static std::string message(int done) {
        return "rayo: interrupted: " + std::to_string(done) + " of " + std::to_string(kTiles) +
               " tiles done; resume with --resume";
    }
};

// Interrupted once and twice, then resumed with another thread count: the same bits as the
// uninterrupted render, streamed and in memory, EXR and PNG; nothing under the output's name
// (nor a temporary) while interrupted, and no partial render once complete.
TEST_F(ResumeCli, ResumedRendersAreBitIdenticalToUninterruptedOnes) {
    write("scene.nff", kSceneNff);
    for (const std::string ext : {".exr", ".png"}) {
        for (const std::string stream : {"--stream", "--no-stream"}) {
            const std::string label = ext + " " + stream;
            const CommandResult reference =
                run("render scene.nff --tile-size 16 " + stream + " -o reference" + ext);
            ASSERT_EQ(reference.exit_code, 0) << reference.output;
            EXPECT_EQ(listing(), (std::set<std::string>{"scene.nff", "reference" + ext}))
                << label << ": an uninterrupted render leaves no partial render";

            const std::string out = "-o out" + ext + " " + stream;
            const std::string partial = "out" + ext + ".rayo-partial";
            const CommandResult first = interrupted(out, 5);
            EXPECT_EQ(first.exit_code, 130) << label << "\n" << first.output;
            EXPECT_NE(first.output.find(message(5)), std::string::npos) << first.output;
            EXPECT_EQ(listing(), (std::set<std::string>{"scene.nff", "reference" + ext, partial}))
                << label;

            const CommandResult second = interrupted(out + " --resume", 20);
            EXPECT_EQ(second.exit_code, 130) << label << "\n" << second.output;
            EXPECT_NE(second.output.find("rayo: resuming " + partial +
                                         ": 5 of 70 tiles done, "
                                         "65 to render"),
                      std::string::npos)
                << second.output;
            EXPECT_NE(second.output.find(message(25)), std::string::npos) << second.output;
            EXPECT_EQ(listing(), (std::set<std::string>{"scene.nff", "reference" + ext, partial}))
                << label;

            const CommandResult last =
                run("render scene.nff --tile-size 16 --threads 2 --resume " + out);
            ASSERT_EQ(last.exit_code, 0) << label << "\n" << last.output;
            EXPECT_NE(last.output.find("25 of 70 tiles done, 45 to render"), std::string::npos)
                << last.output;
            EXPECT_EQ(listing(),
                      (std::set<std::string>{"scene.nff", "reference" + ext, "out" + ext}))
                << label;
            const std::vector<unsigned char> expected = stored("reference" + ext);
            ASSERT_FALSE(expected.empty());
            EXPECT_TRUE(stored("out" + ext) == expected) << label << ": pixels differ";
            std::filesystem::remove(m_dir / ("out" + ext));
            std::filesystem::remove(m_dir / ("reference" + ext));
        }
    }
}

TEST_F(ResumeCli, SigtermExitsWith143AndKeepsTheTiles) {
    write("scene.nff", kSceneNff);
    const CommandResult r = interrupted("-o out.exr", 3, ":TERM");
    EXPECT_EQ(r.exit_code, 143) << r.output;
    EXPECT_NE(r.output.find("rayo: terminated (SIGTERM): finishing the tiles in flight"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(message(3)), std::string::npos) << r.output;
    EXPECT_EQ(listing(), (std::set<std::string>{"scene.nff", "out.exr.rayo-partial"}));
}

// A resume with another scene or other settings is refused, naming each difference, and the
// partial render stays; a fresh render does not discard it either.
TEST_F(ResumeCli, ResumeRefusesOtherSettingsNamingThem) {
    write("scene.nff", kSceneNff);
    ASSERT_EQ(interrupted("-o out.exr", 4).exit_code, 130);
    const std::set<std::string> kept{"scene.nff", "out.exr.rayo-partial"};
    struct Case {
        std::string args, expected;
    };
    const std::vector<Case> cases = {
        {"--spp 2", "spp: 1 in the partial render, 2 now"},
        {"--width 160 --height 100", "resolution: 150x100 in the partial render, 160x100 now"},
        {"--max-depth 2", "max depth: 5 in the partial render, 2 now"},
        {"--tile-size 32", "tile size: 16 in the partial render, 32 now"},
        {"--sphere-math seed", "sphere math: stable in the partial render, seed now"},
    };
    for (const Case& c : cases) {
        const std::string tile =
            c.args.find("--tile-size") == std::string::npos ? " --tile-size 16" : "";
        const CommandResult r = run("render scene.nff -o out.exr --resume" + tile + " " + c.args);
        EXPECT_EQ(r.exit_code, 1) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find("rayo: error: out.exr: --resume: the partial render "
                                "'out.exr.rayo-partial' was made with other settings:"),
                  std::string::npos)
            << r.output;
        EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_EQ(listing(), kept) << c.args;
    }
    // The scene's contents, even under the same name.
    write("scene.nff", std::string(kSceneNff) + "s 0 -1 0 0.3\n");
    const CommandResult changed = run("render scene.nff -o out.exr --resume --tile-size 16");
    EXPECT_EQ(changed.exit_code, 1) << changed.output;
    EXPECT_NE(changed.output.find("scene contents: "), std::string::npos) << changed.output;
    EXPECT_EQ(listing(), kept);

    const CommandResult fresh = run("render scene.nff -o out.exr --tile-size 16");
    EXPECT_EQ(fresh.exit_code, 1) << fresh.output;
    EXPECT_NE(fresh.output.find("rayo: error: out.exr: a partial render of this output exists "
                                "('out.exr.rayo-partial'): continue it with --resume"),
              std::string::npos)
        << fresh.output;
    EXPECT_EQ(listing(), kept);
}

// The files the scene references are in the fingerprint too (issue "Robustness, round three",
// item 12): a texture replaced between the interruption and the resume gave an image half the
// old texture, half the new (exit 0). Now the resume names the file and refuses.
TEST_F(ResumeCli, ResumeRefusesAReferencedFileThatChanged) {
    ASSERT_EQ(run("render --width 64 --height 64 -o tex.png").exit_code, 0);
    write("scene.json", R"({"rayo": 1, "camera": {"eye": [0, 0, 3], "look_at": [0, 0, 0],
        "vfov": 40, "width": 150, "height": 100},
        "lights": [{"type": "point", "position": [2, 2, 3]}],
        "materials": {"m": {"kd": {"image": "tex.png"}}},
        "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})");
    const std::string render = "render scene.json -o out.exr --tile-size 16 --threads 1";
    ASSERT_EQ(run(render + " --journal-after 0", "RAYO_TEST_INTERRUPT=4").exit_code, 130);
    // Unchanged, the resume completes.
    ASSERT_EQ(run(render + " --resume", "RAYO_TEST_INTERRUPT=8").exit_code, 130);
    // Another texture under the same name.
    ASSERT_EQ(run("render --width 32 --height 32 -o tex.png").exit_code, 0);
    const CommandResult r = run(render + " --resume");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("was made with other settings:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("  file tex.png: "), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(m_dir / "out.exr"));
}

TEST_F(ResumeCli, ResumeWithoutAPartialRenderIsRefused) {
    write("scene.nff", kSceneNff);
    const CommandResult r = run("render scene.nff -o out.exr --resume");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("rayo: error: out.exr: --resume: cannot open the partial render "
                            "'out.exr.rayo-partial': No such file or directory (nothing to "
                            "resume)"),
              std::string::npos)
        << r.output;
    const CommandResult both = run("render scene.nff -o out.exr --resume --no-journal");
    EXPECT_EQ(both.exit_code, 2) << both.output;
    EXPECT_EQ(listing(), std::set<std::string>{"scene.nff"});
}

// Something else under the partial render's name (a dangling symbolic link, a directory) is
// named for what it is before the render starts, not taken for a render running now.
TEST_F(ResumeCli, ALinkOrDirectoryAtThePartialRendersNameIsNamed) {
    write("scene.nff", kSceneNff);
    std::filesystem::create_symlink("nowhere", m_dir / "out.exr.rayo-partial");
    const CommandResult r = run("render scene.nff -o out.exr --journal-after 0");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("'out.exr.rayo-partial' exists and is a symbolic link, not a partial "
                            "render rayo wrote"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("running now"), std::string::npos) << r.output;
    std::filesystem::remove(m_dir / "out.exr.rayo-partial");
    std::filesystem::create_directory(m_dir / "out.exr.rayo-partial");
    const CommandResult d = run("render scene.nff -o out.exr --journal-after 0");
    EXPECT_EQ(d.exit_code, 1) << d.output;
    EXPECT_NE(d.output.find("exists and is not a regular file"), std::string::npos) << d.output;
    EXPECT_EQ(listing().count("out.exr"), 0u);
}

// Tiles finished before --journal-after seconds into the render are not kept (2 s by default):
// interrupted before, a render keeps nothing, says so, and leaves no file.
TEST_F(ResumeCli, TilesBeforeJournalAfterAreNotKept) {
    write("scene.nff", kSceneNff);
    for (const std::string after : {"", "--journal-after 3600 "}) {
        const CommandResult r =
            run("render scene.nff --tile-size 16 --threads 1 " + after + "-o out.exr",
                "RAYO_TEST_INTERRUPT=3");
        EXPECT_EQ(r.exit_code, 130) << after << "\n" << r.output;
        EXPECT_NE(r.output.find("rayo: interrupted: 0 of 70 tiles done; nothing kept (tiles are "
                                "kept from --journal-after seconds into a render on)"),
                  std::string::npos)
            << r.output;
        EXPECT_EQ(listing(), std::set<std::string>{"scene.nff"}) << after;
    }
}

// --journal-after takes a finite number of seconds, at least 0, and only for a new render that
// keeps a partial render.
TEST_F(ResumeCli, JournalAfterIsChecked) {
    write("scene.nff", kSceneNff);
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--journal-after -1", "--journal-after: expected a number in [0, 1e+06], got '-1'"},
        {"--journal-after nan", "--journal-after: expected a number in [0, 1e+06], got 'nan'"},
        {"--journal-after 2s", "--journal-after: expected a number in [0, 1e+06], got '2s'"},
        {"--journal-after 1 --no-journal", "--journal-after and --no-journal exclude each other"},
        {"--journal-after 1 --resume", "--journal-after: a resumed render keeps every tile"},
    };
    for (const auto& [args, expected] : cases) {
        const CommandResult r = run("render scene.nff -o out.exr " + args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("rayo: error: " + expected), std::string::npos) << args << "\n"
                                                                                << r.output;
        EXPECT_EQ(listing(), std::set<std::string>{"scene.nff"}) << args;
    }
}

// What kill -9 or a power loss leaves: a record cut short, a record with other bytes. Both
// tiles are rendered again; the others are taken from the file; the image is the same bits.
TEST_F(ResumeCli, TornRecordsAreRenderedAgain) {
    write("scene.nff", kSceneNff);
    ASSERT_EQ(run("render scene.nff --tile-size 16 -o reference.png").exit_code, 0);
    ASSERT_EQ(interrupted("-o out.png", 6).exit_code, 130);
    const std::filesystem::path partial = m_dir / "out.png.rayo-partial";
    // One thread records tiles 0..5 in order: flip a pixel byte of tile 1, cut tile 5 short.
    {
        std::fstream file(partial, std::ios::in | std::ios::out | std::ios::binary);
        file.seekg(kHeaderBytes + 1 * kSlotBytes + 32 + 100);
        char byte = 0;
        file.read(&byte, 1);
        byte = static_cast<char>(byte ^ 0x10);
        file.seekp(kHeaderBytes + 1 * kSlotBytes + 32 + 100);
        file.write(&byte, 1);
    }
    std::filesystem::resize_file(partial, kHeaderBytes + 5 * kSlotBytes + 32 + 1000);
    const CommandResult r = run("render scene.nff --tile-size 16 -o out.png --resume");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("4 of 70 tiles done, 66 to render"), std::string::npos) << r.output;
    EXPECT_TRUE(stored("out.png") == stored("reference.png"));
    EXPECT_EQ(listing(), (std::set<std::string>{"scene.nff", "reference.png", "out.png"}));
}

// A partial render that cannot grow (here the file-size limit; a full disk alike) does not fail
// the render: a warning names the reason, and the output is whole.
TEST_F(ResumeCli, AFailingPartialRenderDoesNotFailTheRender) {
    write("scene.nff", kSceneNff);
    ASSERT_EQ(run("render scene.nff --tile-size 16 -o reference.png").exit_code, 0);
    const WatchedResult r = run_watched({"render", "scene.nff", "--tile-size", "16", "--threads",
                                         "1", "--journal-after", "0", "-o", "out.png"},
                                        60.0, {}, kHeaderBytes + 20 * kSlotBytes);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("rayo: warning: out.png: partial render 'out.png.rayo-partial': "
                            "cannot write: File too large; the render went on without keeping "
                            "its tiles"),
              std::string::npos)
        << r.output;
    EXPECT_TRUE(stored("out.png") == stored("reference.png"));
    EXPECT_EQ(listing(), (std::set<std::string>{"scene.nff", "reference.png", "out.png"}));
}

// A real kill -9 in the middle of a render: resuming gives the uninterrupted image.
TEST_F(ResumeCli, ResumeAfterKillMinus9) {
    write("scene.nff", kSceneNff);
    const std::string args = " --width 600 --height 400 --spp 4 --tile-size 16 --threads 1";
    ASSERT_EQ(run("render scene.nff -o reference.exr" + args).exit_code, 0);
    bool killed = false;
    const WatchedResult r = run_watched(
        {"render", "scene.nff", "--width", "600", "--height", "400", "--spp", "4", "--tile-size",
         "16", "--threads", "1", "--journal-after", "0", "-o", "out.exr"},
        120.0, [&](pid_t pid) {
            std::error_code ec;
            if (std::filesystem::file_size(m_dir / "out.exr.rayo-partial", ec) <
                    kHeaderBytes + 20 * kSlotBytes ||
                ec)
                return false;
            ::kill(pid, SIGKILL);
            killed = true;
            return true;
        });
    ASSERT_TRUE(killed) << r.output;
    EXPECT_EQ(r.shell_status, 128 + SIGKILL);
    EXPECT_FALSE(std::filesystem::exists(m_dir / "out.exr"));
    const CommandResult resumed = run("render scene.nff -o out.exr --resume" + args);
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_EQ(resumed.output.find("rayo: resuming out.exr.rayo-partial: 0 of"), std::string::npos)
        << resumed.output;
    EXPECT_TRUE(stored("out.exr") == stored("reference.exr"));
    EXPECT_EQ(listing(), (std::set<std::string>{"scene.nff", "reference.exr", "out.exr"}));
}

}  // namespace
