// `rayo texture NAME`: the texture laid flat, written through the CLI, and its flag errors.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "apps/cli/cli.h"
#include "core/camera.h"
#include "shading/texture.h"

namespace rayo {
namespace {

// ---- `rayo texture NAME` ---------------------------------------------------------------------

int cli(std::vector<std::string> args, std::string* err_text = nullptr) {
    args.insert(args.begin(), "rayo");
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    std::ostringstream out, err;
    const int rc = run_cli(static_cast<int>(argv.size()), argv.data(), out, err);
    if (err_text) *err_text = err.str();
    return rc;
}

// The help names every texture kind, from their one list (shading/texture.h).
TEST(TextureCli, HelpListsEveryTextureKind) {
    const char* argv[] = {"rayo", "texture", "--help"};
    std::ostringstream out, err;
    ASSERT_EQ(run_cli(3, argv, out, err), 0);
    const std::string help = out.str();
    const std::string line = "NAME is one of (docs/textures.md):\n  " + texture_kind_list() + "\n";
    EXPECT_NE(help.find(line), std::string::npos) << help;
    for (const std::string& kind : texture_kind_names()) {
        EXPECT_NE(help.find(kind), std::string::npos) << kind;
    }
}

TEST(TextureCli, WritesTheTextureFlatAndRefusesBadFlags) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("rayo_texture_cli_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string exr = (dir / "pool.exr").string();
    ASSERT_EQ(cli({"texture", "pool-bottom", "-o", exr, "--size", "40x24", "--seed", "3"}), 0);
    auto in = OIIO::ImageInput::open(exr);
    ASSERT_TRUE(in);
    const OIIO::ImageSpec& spec = in->spec();
    ASSERT_EQ(spec.width, 40);
    ASSERT_EQ(spec.height, 24);
    std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    in->close();
    // Exactly the texture's colours at the pixel centres of the plane z = 0, 64 px per unit.
    Texture t = make_texture("pool-bottom");
    t.seed = 3;
    for (int j = 0; j < 24; j += 5) {
        for (int i = 0; i < 40; i += 7) {
            const Vec3 c = t.color(Vec3((i + 0.5f) / 64.0f, (24 - j - 0.5f) / 64.0f, 0.0f));
            const float* p = &pixels[(static_cast<size_t>(j) * 40 + i) * spec.nchannels];
            EXPECT_FLOAT_EQ(p[0], c.x);
            EXPECT_FLOAT_EQ(p[1], c.y);
            EXPECT_FLOAT_EQ(p[2], c.z);
        }
    }
    for (const char* name : {"perlin", "cellular", "marble"}) {
        EXPECT_EQ(cli({"texture", name, "-o", (dir / (std::string(name) + ".png")).string(),
                       "--size", "16x16", "--scale", "0.5"}),
                  0)
            << name;
    }
    std::string err;
    EXPECT_EQ(cli({"texture", "plaid"}, &err), 2);
    EXPECT_NE(err.find("pool-bottom"), std::string::npos);
    EXPECT_EQ(cli({"texture"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--size", "16"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--size", "0x16"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--scale", "inf"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--scale", "0"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--seed", "-1"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "--bogus"}), 2);
    EXPECT_EQ(cli({"texture", "perlin", "-o", (dir / "x.unknown").string()}), 1);
    std::filesystem::remove_all(dir);
}

// Each flag's bound is declared once (kTextureFlags): --help states it and the parser refuses a
// value beyond it with the same numbers, naming the flag; the size's bound is the image's
// (kMaxImageSide, as --width and "camera": {"width"}).
TEST(TextureCli, HelpStatesTheBoundsTheParserEnforces) {
    const char* argv[] = {"rayo", "texture", "--help"};
    std::ostringstream out, err;
    ASSERT_EQ(run_cli(3, argv, out, err), 0);
    const std::string help = out.str();
    const std::string side = std::to_string(kMaxImageSide);
    for (const std::string& text : std::vector<std::string>{
             "--scale S", "a number in [1e-06, 1e+06]", "--seed N", "0..2147483647", "--size WxH",
             std::string("WxH, each 1..") + side, "-o, --output FILE"}) {
        EXPECT_NE(help.find(text), std::string::npos) << text << "\n" << help;
    }
    const struct {
        std::vector<std::string> args;
        std::string message;
    } refused[] = {
        {{"--scale", "2e6"}, "--scale: expected a number in [1e-06, 1e+06], got '2e6'"},
        {{"--scale", "0"}, "--scale: expected a number in [1e-06, 1e+06], got '0'"},
        {{"--seed", "2147483648"},
         "--seed: expected an integer in [0, 2147483647], got '2147483648'"},
        {{"--seed", "-1"}, "--seed: expected an integer in [0, 2147483647], got '-1'"},
        {{"--size", "16"}, "--size: expected WxH, each 1.." + side + ", got '16'"},
        {{"--size", "0x16"}, "--size width: expected an integer in [1, " + side + "], got '0'"},
        {{"--size", "16x" + std::to_string(kMaxImageSide + 1)},
         "--size height: expected an integer in [1, " + side + "], got '" +
             std::to_string(kMaxImageSide + 1) + "'"},
        {{"--seed"}, "--seed: missing value"},
        {{"--bogus"}, "unknown option '--bogus' (see rayo texture --help)"},
    };
    for (const auto& r : refused) {
        std::vector<std::string> args = {"texture", "perlin"};
        args.insert(args.end(), r.args.begin(), r.args.end());
        std::string message;
        EXPECT_EQ(cli(args, &message), 2) << r.message;
        EXPECT_EQ(message, "rayo: error: " + r.message + "\n");
    }
}
}  // namespace
}  // namespace rayo
