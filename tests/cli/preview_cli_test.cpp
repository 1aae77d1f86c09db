// `rayo preview`: the wireframe written through the executable (size, lines, black or the dim
// render under them, the summary) and the help. Its bad input is in bad_input_test.cpp.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/cli/cli_fixture.h"

namespace {

using rayo_test::CommandResult;

// A sphere in front of an NFF camera, lit, on a grey background.
const char* const kSphereNff =
    "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 64 48\n"
    "b 0.5 0.5 0.5\nl 3 3 3\nf 1 0 0 0.8 0.2 20 0 1\ns 0.3 0.2 0 1\n";

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgba;
    int count(bool (*test)(const float*)) const {
        int n = 0;
        for (size_t i = 0; i < rgba.size(); i += 4) n += test(&rgba[i]);
        return n;
    }
};

Image read_exr(const std::string& path) {
    Image image;
    auto in = OIIO::ImageInput::open(path);
    if (!in) return image;
    image.width = in->spec().width;
    image.height = in->spec().height;
    EXPECT_EQ(in->spec().nchannels, 4);
    image.rgba.resize(static_cast<size_t>(image.width) * image.height * 4);
    EXPECT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, image.rgba.data()));
    return image;
}

class PreviewCli : public rayo_test::CliFixture {};

TEST_F(PreviewCli, LinesOnBlackAtTheRequestedSize) {
    write("sphere.nff", kSphereNff);
    const CommandResult r = run("preview sphere.nff -o wire.exr --width 80 --height 60");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("wire.exr 80x60 preview | 1 objects (1 spheres"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("segments "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(" drawn ("), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(" clipped away ("), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("| total "), std::string::npos) << r.output;
    const Image image = read_exr((m_dir / "wire.exr").string());
    ASSERT_EQ(image.width, 80);
    ASSERT_EQ(image.height, 60);
    const int lit = image.count([](const float* p) { return p[0] + p[1] + p[2] > 0.0f; });
    EXPECT_GT(lit, 60);       // the sphere's silhouette: a ring of about 2π·15 pixels
    EXPECT_LT(lit, 80 * 20);  // and not the background
}

TEST_F(PreviewCli, OverRenderShowsTheDimRenderUnderTheLines) {
    write("sphere.nff", kSphereNff);
    const CommandResult r = run("preview sphere.nff -o wire.exr --over-render --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output, "");
    const Image image = read_exr((m_dir / "wire.exr").string());
    ASSERT_EQ(image.width, 64);
    // The grey background, darkened: no pixel is black any more.
    EXPECT_EQ(image.count([](const float* p) { return p[0] + p[1] + p[2] == 0.0f; }), 0);
}

TEST_F(PreviewCli, DefaultOutputIsTheScenesNameWithPreview) {
    write("sphere.nff", kSphereNff);
    const CommandResult r = run("preview sphere.nff --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(m_dir / "sphere-preview.png"));
}

TEST_F(PreviewCli, HelpDescribesTheCommand) {
    const CommandResult r = run("preview --help");
    ASSERT_EQ(r.exit_code, 0);
    EXPECT_NE(r.output.find("rayo preview [SCENE] [options]"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--over-render"), std::string::npos) << r.output;
}

}  // namespace
