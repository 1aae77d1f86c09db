// --texture-filter (render.texture_filter, shading/mip_pyramid.h): the flag is listed, takes
// bilinear or bicubic, and refuses anything else before any work (exit 2, no file).
#include <gtest/gtest.h>

#include <string>

#include "tests/cli/cli_fixture.h"

namespace {

using rayo_test::CommandResult;

class TextureFilterCli : public rayo_test::CliFixture {};

TEST_F(TextureFilterCli, TakesBilinearOrBicubicAndRefusesTheRest) {
    const CommandResult help = run("render --help");
    ASSERT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find("--texture-filter bilinear|bicubic"), std::string::npos)
        << help.output;
    for (const char* filter : {"bilinear", "bicubic"}) {
        EXPECT_EQ(run(std::string("render --width 8 --height 8 --quiet --texture-filter ") +
                      filter + " -o " + filter + ".exr")
                      .exit_code,
                  0)
            << filter;
    }
    const CommandResult bad = run("render --texture-filter trilinear -o bad.exr");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.output.find("--texture-filter"), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find("trilinear"), std::string::npos) << bad.output;
    EXPECT_EQ(listing().count("bad.exr"), 0u);
}

}  // namespace
