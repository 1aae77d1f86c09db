// `rayo render`'s options declared once (apps/cli/render_options.h): the help lists every one,
// and a library caller that names them gets the command line's parser, bounds and messages,
// with each option confined to the call it belongs to.
#include "apps/cli/render_options.h"

#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "apps/cli/cli.h"
#include "apps/cli/usage_error.h"
#include "apps/scene/default_scene.h"

namespace {

using rayo::OptionUse;
using rayo::RenderOptionInfo;
using rayo::UsageError;

std::string render_help() {
    std::ostringstream out, err;
    const char* const argv[] = {"rayo", "render", "--help"};
    EXPECT_EQ(rayo::run_cli(3, argv, out, err), 0) << err.str();
    return out.str();
}

// The message of the UsageError `f` throws ("" when it throws none).
template <typename F>
std::string usage_error(F f) {
    try {
        f();
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

TEST(RenderOptions, TheHelpListsEveryOptionOnce) {
    const std::string help = render_help();
    const std::vector<RenderOptionInfo> options = rayo::render_option_list();
    EXPECT_GT(options.size(), 40u);
    for (const RenderOptionInfo& o : options) {
        // A flag starts a help line, alone or after the option it shares the line with.
        const bool listed = help.find("  " + o.flag + " ") != std::string::npos ||
                            help.find("  " + o.flag + "\n") != std::string::npos ||
                            help.find("  " + o.flag + ",") != std::string::npos ||
                            help.find(", " + o.flag) != std::string::npos;
        EXPECT_TRUE(listed) << o.flag;
        EXPECT_FALSE(o.help.empty()) << o.flag;
    }
    for (const char* flag : {"--spp", "--max-depth", "--ao-samples", "--sphere-method",
                             "--view-dir", "--exr-compression", "--resume"}) {
        size_t count = 0;
        for (const RenderOptionInfo& o : options) count += o.flag == flag;
        EXPECT_EQ(count, 1u) << flag;
    }
}

TEST(RenderOptions, ALibraryCallerGetsTheCommandLinesParserAndBounds) {
    rayo::SceneDescription d = rayo::make_default_scene();
    const int width = d.scene.camera.width, height = d.scene.camera.height;
    EXPECT_EQ(rayo::apply_render_options({"--width", "64", "--spp", "4", "--threads", "3",
                                          "--sphere-method", "mesh:2", "--single-rays"},
                                         d),
              3);
    EXPECT_EQ(d.scene.camera.width, 64);
    EXPECT_EQ(d.scene.camera.height, static_cast<int>(std::lround(64.0 * height / width)));
    EXPECT_EQ(d.settings.spp, 4);
    EXPECT_FALSE(d.settings.coherent);
    EXPECT_EQ(d.settings.spheres.method, rayo::SphereMethod::Mesh);
    // The command line's messages, word for word.
    EXPECT_EQ(usage_error([&] {
                  rayo::apply_render_options({"--spp", "0"}, d);
              }),
              "--spp: expected an integer in [1, 65536], got '0'");
    EXPECT_NE(usage_error([&] {
                  rayo::apply_render_options({"--sphere-method", "x"}, d);
              }).find("--sphere-method: expected one of \"auto\", \"user\""),
              std::string::npos);
    EXPECT_EQ(usage_error([&] {
                  rayo::apply_render_options({"--ao-samples", "8"}, d);
              }),
              "--ao-samples: a setting of the \"ambient_occlusion\" integrator, but this "
              "render's integrator is \"whitted\" (--integrator chooses)");
}

TEST(RenderOptions, EachOptionBelongsToOneCall) {
    rayo::SceneDescription d = rayo::make_default_scene();
    EXPECT_EQ(usage_error([&] { rayo::apply_render_options({"--stream"}, d); }),
              "--stream: an option of the command line only, not an option of the render");
    EXPECT_EQ(usage_error([&] {
                  rayo::apply_render_options({"--view-dir", "0,0,1"}, d);
              }),
              "--view-dir: an option of reading the scene, not an option of the render");
    EXPECT_EQ(usage_error([&] {
                  rayo::load_scene_with_options(std::nullopt, {"--spp", "2"});
              }),
              "--spp: an option of the render, not an option of reading the scene");
    EXPECT_EQ(usage_error([&] {
                  rayo::output_options_from({"--half", "--width", "3"});
              }),
              "--width: an option of the render, not an option of writing the image");
    const rayo::OutputOptions o = rayo::output_options_from({"--half", "--exr-compression", "piz"});
    EXPECT_TRUE(o.half_float_exr);
    EXPECT_EQ(o.exr_compression, "piz");
    std::map<std::string, OptionUse> uses;
    for (const RenderOptionInfo& info : rayo::render_option_list()) uses[info.flag] = info.use;
    EXPECT_EQ(uses.at("--half"), OptionUse::Output);
    EXPECT_EQ(uses.at("--environment"), OptionUse::Load);
    EXPECT_EQ(uses.at("--max-depth"), OptionUse::Render);
    EXPECT_EQ(uses.at("--journal-after"), OptionUse::Command);
}

}  // namespace
