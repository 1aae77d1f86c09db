// `rayo render --time-limit / --noise-target` (core/progressive.h): the summary says how many
// samples each pixel got and why the render stopped, the file's metadata gives them, and bad
// values and combinations are refused before any work, with no output left.
#include <OpenImageIO/imageio.h>

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
        {"--noise-target 0.1 --resume", "a progressive render"},
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

TEST_F(ProgressiveCli, HelpListsTheProgressiveSettingsAsOffByDefault) {
    const CommandResult r = run("render --help");
    ASSERT_EQ(r.exit_code, 0);
    for (const char* flag : {"--time-limit X", "--noise-target X", "--pass-spp N", "--max-spp N"}) {
        EXPECT_NE(r.output.find(flag), std::string::npos) << flag;
    }
    EXPECT_NE(r.output.find("default off"), std::string::npos) << r.output;
}

}  // namespace
