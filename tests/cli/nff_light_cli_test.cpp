// `rayo render --nff-light-intensity X` end to end: NFF lights at 1/sqrt(N) by default (the SPD's
// rule), X in their place when given, and bad values refused with the flag's name.
#include <OpenImageIO/imagebuf.h>

#include <filesystem>
#include <string>

#include "tests/cli/cli_fixture.h"

namespace fs = std::filesystem;

namespace {

using rayo_test::CommandResult;

// A white diffuse square (Kd 1, ambient 0.1 × white) facing the camera, lit by four uncoloured
// lights at the eye: at the centre pixel N·L = 1 for each light, so the pixel is
// 0.1 + 4 × intensity (no highlight, mirror or transmission; black background).
const char* const kFourLights =
    "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 30\nhither 0.01\nresolution 9 9\n"
    "b 0 0 0\nl 0 0 5\nl 0 0 5\nl 0 0 5\nl 0 0 5\nf 1 1 1 1 0 1 0 1\n"
    "p 4\n-10 -10 0\n10 -10 0\n10 10 0\n-10 10 0\n";

class NffLightCliTest : public rayo_test::CliFixture {
  protected:
    // Red channel of the centre pixel of a rendered EXR (linear, as rendered).
    float centre_red(const std::string& name) const {
        OIIO::ImageBuf image((m_dir / name).string());
        float pixel[4] = {};
        EXPECT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << image.geterror();
        image.getpixel(4, 4, pixel, 4);
        return pixel[0];
    }
};

TEST_F(NffLightCliTest, DefaultIsOneOverSqrtNAndTheFlagReplacesIt) {
    write("four.nff", kFourLights);
    struct Case {
        const char* flag;
        float expected;  // 0.1 + 4 × intensity
    };
    const Case cases[] = {
        {"", 0.1f + 4.0f * 0.5f},                               // 1/sqrt(4)
        {"--nff-light-intensity 1", 0.1f + 4.0f * 1.0f},        // unit lights
        {"--nff-light-intensity 0.125", 0.1f + 4.0f * 0.125f},  //
        {"--nff-light-intensity 0", 0.1f},                      // ambient only
    };
    for (const Case& c : cases) {
        const CommandResult r = run(std::string("render four.nff --quiet -o out.exr ") + c.flag);
        ASSERT_EQ(r.exit_code, 0) << c.flag << ": " << r.output;
        EXPECT_NEAR(centre_red("out.exr"), c.expected, 1e-4f) << c.flag;
    }
}

TEST_F(NffLightCliTest, OtherScenesSayTheFlagDoesNothing) {
    const CommandResult r = run("render -o out.png --nff-light-intensity 1");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("warning: --nff-light-intensity applies to NFF scenes only; ignored"),
              std::string::npos)
        << r.output;
    write("four.nff", kFourLights);
    const CommandResult nff = run("render four.nff -o out.exr --nff-light-intensity 1");
    EXPECT_EQ(nff.output.find("applies to NFF scenes only"), std::string::npos) << nff.output;
}

TEST_F(NffLightCliTest, BadValuesAreRefusedNamingTheFlag) {
    write("four.nff", kFourLights);
    // The upper bound only keeps the value finite: read_real (core/setting.h) does not say it.
    const std::string expected = "--nff-light-intensity: expected a number >= 0, got ";
    for (const char* value : {"-1", "-0.001", "nan", "inf", "1e40", "1x", "''", "abc"}) {
        const CommandResult r =
            run(std::string("render four.nff -o x.exr --nff-light-intensity ") + value);
        EXPECT_EQ(r.exit_code, 2) << value << ": " << r.output;
        EXPECT_NE(r.output.find(expected), std::string::npos) << value << " -> " << r.output;
        EXPECT_FALSE(fs::exists(m_dir / "x.exr")) << value;
    }
    const CommandResult r = run("render four.nff -o x.exr --nff-light-intensity");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("--nff-light-intensity: missing value"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(m_dir / "x.exr"));
}

TEST_F(NffLightCliTest, HelpDescribesTheFlag) {
    const CommandResult r = run("render --help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.output.find("--nff-light-intensity X"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("1/sqrt(number of lights)"), std::string::npos) << r.output;
}

}  // namespace
