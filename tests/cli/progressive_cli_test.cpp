// `rayo render --time-limit / --noise-target` (core/progressive.h): the summary says how many
// samples each pixel got and why the render stopped, the file's metadata gives them, and bad
// values and combinations are refused before any work, with no output left.
#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli/cli_fixture.h"

namespace {

using rayo_test::CommandResult;

class ProgressiveCli : public rayo_test::CliFixture {};

// A diffuse sphere on a floor under a disk light, 32 × 24.
const char* const kScene = R"({"rayo": 1, "background": [0, 0, 0],
  "camera": {"eye": [0, 2, 6], "look_at": [0, 0.6, 0], "width": 32, "height": 24},
  "lights": [{"type": "area", "shape": "disk", "center": [0, 4, 0], "normal": [0, -1, 0],
              "radius": 1, "intensity": 6}],
  "materials": {"default": {"ka": 0, "kd": 0.7, "ks": 0}},
  "render": {"integrator": {"type": "path", "max_depth": 4}},
  "objects": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 10},
              {"type": "sphere", "center": [0, 1, 0], "radius": 1}]})";

TEST_F(ProgressiveCli, TheSummaryGivesTheSamplesAndWhyTheRenderStopped) {
    write("scene.json", kScene);
    const CommandResult r = run("render scene.json --noise-target 0.1 --pass-spp 4 -o p.exr");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("passes, noise "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("stopped by the noise target)"), std::string::npos) << r.output;
    auto in = OIIO::ImageInput::open((m_dir / "p.exr").string());
    ASSERT_TRUE(in);
    const std::string spp = in->spec().get_string_attribute("rayo:spp");
    // The samples each pixel got, a whole number of passes of 4, as the summary says.
    ASSERT_FALSE(spp.empty());
    EXPECT_EQ(std::stoi(spp) % 4, 0) << spp;
    EXPECT_NE(r.output.find(" " + spp + "spp ("), std::string::npos) << r.output;

    const CommandResult capped =
        run("render scene.json --time-limit 1000 --max-spp 8 --pass-spp 4 -o c.exr");
    ASSERT_EQ(capped.exit_code, 0) << capped.output;
    EXPECT_NE(capped.output.find(" 8spp (2 passes, noise "), std::string::npos) << capped.output;
    EXPECT_NE(capped.output.find("stopped by the sample cap)"), std::string::npos) << capped.output;
}

TEST_F(ProgressiveCli, BadValuesAndCombinationsAreRefusedBeforeAnyWork) {
    write("scene.json", kScene);
    struct Case {
        std::string args, message;
    };
    const Case cases[] = {
        {"--time-limit 0", "--time-limit"},
        {"--time-limit -1", "--time-limit"},
        {"--time-limit nan", "--time-limit"},
        {"--noise-target 0", "--noise-target"},
        {"--noise-target -0.5", "--noise-target"},
        {"--pass-spp 1", "--pass-spp"},
        {"--noise-target 0.1 --aa adaptive", "own stopping rule"},
        {"--time-limit 1 --max-spp 2", "is below one pass"},
        {"--max-spp 1", "--max-spp"},
        {"--noise-target 0.1 --resume", "--resume: no passes of a progressive render"},
        {"--noise-target 0.1 --width 8193 --height 8192",
         "is too large for a progressive render (time_limit, noise_target): at most 67108864"},
    };
    for (const Case& c : cases) {
        const CommandResult r = run("render scene.json -o out.exr " + c.args);
        EXPECT_NE(r.exit_code, 0) << c.args;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_FALSE(std::filesystem::exists(m_dir / "out.exr")) << c.args;
    }
}

// Interrupt and resume (core/image/pass_journal.h): the passes kept go on to the same bits as a
// render never interrupted; a resume may change the stopping rule, not what decides the pixels;
// a kept journal is not overwritten by a new render; a damaged one is refused.
TEST_F(ProgressiveCli, AnInterruptedRenderResumesFromItsPassesToTheSameBits) {
    write("scene.json", kScene);
    const std::string render = "render scene.json --time-limit 1000 --pass-spp 2 --max-spp 12 ";
    ASSERT_EQ(run(render + "-o full.exr --quiet").exit_code, 0);
    // The first run would go on to 24 spp; its resume stops at 12.
    const CommandResult stopped =
        run("render scene.json --time-limit 1000 --pass-spp 2 --max-spp 24 -o part.exr "
            "--journal-after 0",
            "RAYO_TEST_INTERRUPT_PASSES=2");
    ASSERT_EQ(stopped.exit_code, 130) << stopped.output;
    EXPECT_NE(stopped.output.find("kept in part.exr.rayo-passes: resume with --resume"),
              std::string::npos)
        << stopped.output;
    EXPECT_FALSE(std::filesystem::exists(m_dir / "part.exr"));
    ASSERT_TRUE(std::filesystem::exists(m_dir / "part.exr.rayo-passes"));

    const CommandResult other =
        run("render scene.json --time-limit 1000 --pass-spp 4 --max-spp 12 -o part.exr --resume");
    EXPECT_EQ(other.exit_code, 1) << other.output;
    EXPECT_NE(other.output.find("pass spp: 2 in the kept passes, 4 now"), std::string::npos)
        << other.output;
    const CommandResult again = run(render + "-o part.exr");
    EXPECT_EQ(again.exit_code, 1) << again.output;
    EXPECT_NE(again.output.find("continue it with --resume"), std::string::npos) << again.output;
    EXPECT_FALSE(std::filesystem::exists(m_dir / "part.exr"));

    // A lower cap than the first run's: the stopping rule is not in the fingerprint.
    const CommandResult resumed =
        run("render scene.json --time-limit 1000 --pass-spp 2 --max-spp 12 -o part.exr --resume");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_NE(resumed.output.find("rayo: resuming part.exr.rayo-passes: "), std::string::npos)
        << resumed.output;
    EXPECT_NE(resumed.output.find(" 12spp (6 passes, noise "), std::string::npos) << resumed.output;
    EXPECT_EQ(read_pixels("part.exr"), read_pixels("full.exr"));
    EXPECT_FALSE(std::filesystem::exists(m_dir / "part.exr.rayo-passes"));

    // A journal cut short is refused, and left for the user to remove.
    ASSERT_EQ(
        run(render + "-o cut.exr --journal-after 0", "RAYO_TEST_INTERRUPT_PASSES=1").exit_code,
        130);
    const auto journal = m_dir / "cut.exr.rayo-passes";
    std::filesystem::resize_file(journal, std::filesystem::file_size(journal) - 8);
    const CommandResult damaged = run(render + "-o cut.exr --resume");
    EXPECT_EQ(damaged.exit_code, 1) << damaged.output;
    EXPECT_NE(damaged.output.find("bytes of sums where its header says"), std::string::npos)
        << damaged.output;
    EXPECT_FALSE(std::filesystem::exists(m_dir / "cut.exr"));

    // A sum changed on the disk: the checksum says so.
    ASSERT_EQ(
        run(render + "-o flip.exr --journal-after 0", "RAYO_TEST_INTERRUPT_PASSES=1").exit_code,
        130);
    {
        std::fstream file(m_dir / "flip.exr.rayo-passes",
                          std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(-3, std::ios::end);
        file.put('\x5a');
    }
    const CommandResult flipped = run(render + "-o flip.exr --resume");
    EXPECT_EQ(flipped.exit_code, 1) << flipped.output;
    EXPECT_NE(flipped.output.find("do not match their checksum"), std::string::npos)
        << flipped.output;
    EXPECT_FALSE(std::filesystem::exists(m_dir / "flip.exr"));
}

TEST_F(ProgressiveCli, HelpListsTheProgressiveSettingsAsOffByDefault) {
    const CommandResult r = run("render --help");
    ASSERT_EQ(r.exit_code, 0);
    for (const char* flag : {"--time-limit X", "--noise-target X", "--pass-spp N", "--max-spp N"}) {
        EXPECT_NE(r.output.find(flag), std::string::npos) << flag;
    }
    EXPECT_NE(r.output.find("default off"), std::string::npos) << r.output;
}

}  // namespace
