// rayo's MIP maps of image textures (shading/mip_pyramid.h): the levels and their box filter,
// bilinear and bicubic lookups within a level, the wrap modes, the level the footprint picks
// (a checkerboard seen from far away is grey, not aliased), and ImageTextures holding its images
// as MIP maps within the memory limit and the rest in OpenImageIO's cache.
#include "shading/mip_pyramid.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <vector>

#include "shading/image_texture.h"
#include "shading/material.h"

namespace rayo {
namespace {

// A size × size checkerboard of single texels, black and white, 8-bit grey.
std::vector<uint8_t> checkerboard(int size) {
    std::vector<uint8_t> pixels(size_t(size) * size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) pixels[size_t(y) * size + x] = (x + y) % 2 ? 255 : 0;
    }
    return pixels;
}

TEST(MipPyramid, LevelsHalveDownToOneTexelAndKeepTheMean) {
    // 5 × 3 float RGB: odd sides spread their extra texel over the box.
    std::vector<float> pixels;
    double sum = 0.0;
    for (int i = 0; i < 15; ++i) {
        const float v = static_cast<float>(i * i % 7);
        pixels.insert(pixels.end(), {v, 2.0f * v, 0.5f});
        sum += v;
    }
    const MipPyramid pyramid(5, 3, 3, pixels.data());
    ASSERT_EQ(pyramid.levels(), 3);
    EXPECT_EQ(pyramid.width(1), 2);
    EXPECT_EQ(pyramid.height(1), 1);
    EXPECT_EQ(pyramid.width(2), 1);
    EXPECT_EQ(pyramid.height(2), 1);
    EXPECT_EQ(pyramid.bytes(), MipPyramid::bytes_for(5, 3, true));
    EXPECT_EQ(pyramid.bytes(), (15 + 2 + 1) * 4 * sizeof(float));
    // A box filter keeps the mean of the image at every level.
    const double mean = sum / 15.0;
    EXPECT_NEAR(0.5 * (pyramid.texel(1, 0, 0).x + pyramid.texel(1, 1, 0).x), mean, 1e-5);
    EXPECT_NEAR(pyramid.texel(2, 0, 0).x, mean, 1e-5);
    EXPECT_NEAR(pyramid.texel(2, 0, 0).y, 2.0 * mean, 1e-5);
    EXPECT_EQ(pyramid.texel(2, 0, 0).z, 0.5f);
    EXPECT_EQ(pyramid.texel(2, 0, 0).w, 1.0f);  // no alpha: opaque
}

TEST(MipPyramid, GreyAndGreyAlphaBecomeRgba) {
    const uint8_t grey[] = {51};
    const MipPyramid g(1, 1, 1, grey);
    const float grey_value = 51.0f * (1.0f / 255.0f), alpha_value = 102.0f * (1.0f / 255.0f);
    EXPECT_EQ(g.texel(0, 0, 0), glm::vec4(grey_value, grey_value, grey_value, 1.0f));
    const uint8_t grey_alpha[] = {51, 102};
    const MipPyramid ga(1, 1, 2, grey_alpha);
    EXPECT_EQ(ga.texel(0, 0, 0), glm::vec4(grey_value, grey_value, grey_value, alpha_value));
    EXPECT_EQ(MipPyramid::bytes_for(1, 1, false), 4u);
}

TEST(MipPyramid, BilinearIsExactAtTexelCentresAndLinearBetween) {
    const float row[] = {0.0f, 1.0f, 4.0f, 2.0f};  // 4 × 1, grey
    const MipPyramid p(4, 1, 1, row);
    const auto at = [&](float s, TextureWrap wrap) {
        return p.sample_level(0, s, 0.5f, wrap, TextureWrap::Clamp, TextureFilter::Bilinear).x;
    };
    for (int i = 0; i < 4; ++i) EXPECT_EQ(at((i + 0.5f) / 4.0f, TextureWrap::Repeat), row[i]);
    EXPECT_FLOAT_EQ(at(0.25f, TextureWrap::Repeat), 0.5f);  // halfway between texels 0 and 1
    EXPECT_FLOAT_EQ(at(0.5f, TextureWrap::Repeat), 2.5f);
    // At the image's edge: repeat blends the last texel with the first, clamp and mirror hold
    // the edge texel.
    EXPECT_FLOAT_EQ(at(0.0f, TextureWrap::Repeat), 1.0f);
    EXPECT_FLOAT_EQ(at(1.0f, TextureWrap::Repeat), 1.0f);
    EXPECT_FLOAT_EQ(at(0.0f, TextureWrap::Clamp), 0.0f);
    EXPECT_FLOAT_EQ(at(-3.0f, TextureWrap::Clamp), 0.0f);
    EXPECT_FLOAT_EQ(at(7.0f, TextureWrap::Clamp), 2.0f);
    EXPECT_FLOAT_EQ(at(0.0f, TextureWrap::Mirror), 0.0f);
    EXPECT_FLOAT_EQ(at(1.0f, TextureWrap::Mirror), 2.0f);
    // Repeat and mirror continue past [0, 1]: one period on, the same; mirrored, reversed.
    EXPECT_FLOAT_EQ(at(1.0f + 0.625f, TextureWrap::Repeat), row[2]);
    EXPECT_FLOAT_EQ(at(1.0f + 0.125f, TextureWrap::Mirror), row[3]);
    EXPECT_FLOAT_EQ(at(-0.125f, TextureWrap::Mirror), row[0]);
    // Coordinates that are no numbers read the image somewhere, not out of it.
    EXPECT_TRUE(std::isfinite(at(std::nanf(""), TextureWrap::Repeat)));
    EXPECT_TRUE(std::isfinite(at(1e30f, TextureWrap::Mirror)));
}

TEST(MipPyramid, BicubicIsTheCubicBSpline) {
    // One bright texel in a 7 × 7 black image: at its centre the B-spline weighs it (2/3)²,
    // bilinear 1; a constant image stays constant.
    std::vector<float> spot(49, 0.0f);
    spot[3 * 7 + 3] = 1.0f;
    const MipPyramid p(7, 7, 1, spot.data());
    const float centre = 3.5f / 7.0f;
    EXPECT_NEAR(p.sample_level(0, centre, centre, TextureWrap::Clamp, TextureWrap::Clamp,
                               TextureFilter::Bicubic)
                    .x,
                4.0f / 9.0f, 1e-6f);
    EXPECT_EQ(p.sample_level(0, centre, centre, TextureWrap::Clamp, TextureWrap::Clamp,
                             TextureFilter::Bilinear)
                  .x,
              1.0f);
    // A neighbour's centre gets 1/6 · 2/3 of it.
    EXPECT_NEAR(p.sample_level(0, 4.5f / 7.0f, centre, TextureWrap::Clamp, TextureWrap::Clamp,
                               TextureFilter::Bicubic)
                    .x,
                1.0f / 9.0f, 1e-6f);
    std::vector<float> flat(49, 0.3f);
    const MipPyramid constant(7, 7, 1, flat.data());
    std::mt19937 random(3);
    std::uniform_real_distribution<float> uniform(-2.0f, 3.0f);
    for (int i = 0; i < 100; ++i) {
        EXPECT_NEAR(constant
                        .lookup(uniform(random), uniform(random), 0.01f * (i % 7),
                                TextureWrap::Repeat, TextureWrap::Mirror, TextureFilter::Bicubic)
                        .x,
                    0.3f, 1e-6f);
    }
}

// The footprint picks the level: a 256² checkerboard of single texels seen so far away that a
// pixel covers 64 × 64 of its texels averages to grey; looked up without a footprint (the image
// itself) the same points alias to black and white.
TEST(MipPyramid, ACheckerboardSeenFarAwayIsGreyNotAliased) {
    const int size = 256;
    const std::vector<uint8_t> pixels = checkerboard(size);
    const MipPyramid p(size, size, 1, pixels.data());
    EXPECT_EQ(p.levels(), 9);
    std::mt19937 random(5);
    std::uniform_int_distribution<int> texel(0, size - 1);
    int black = 0, white = 0;
    for (int i = 0; i < 1000; ++i) {
        // Texel centres, as a camera far away would happen to hit them.
        const float s = (texel(random) + 0.5f) / size, t = (texel(random) + 0.5f) / size;
        const float far = p.lookup(s, t, 64.0f / size, TextureWrap::Repeat, TextureWrap::Repeat,
                                   TextureFilter::Bilinear)
                              .x;
        EXPECT_NEAR(far, 0.5f, 0.01f) << s << " " << t;
        const float sharp =
            p.lookup(s, t, 0.0f, TextureWrap::Repeat, TextureWrap::Repeat, TextureFilter::Bilinear)
                .x;
        black += sharp == 0.0f;
        white += sharp == 1.0f;
    }
    EXPECT_EQ(black + white, 1000);
    EXPECT_GT(black, 400);
    EXPECT_GT(white, 400);
    // Between the two: a footprint of one texel reads level 0 exactly, two texels level 1 (the
    // checkerboard's 2 × 2 boxes: grey already), 1.5 texels halfway between them.
    const float s = 10.5f / size, t = 20.5f / size;  // a black texel
    const auto at = [&](float width) {
        return p
            .lookup(s, t, width, TextureWrap::Repeat, TextureWrap::Repeat, TextureFilter::Bilinear)
            .x;
    };
    EXPECT_EQ(at(1.0f / size), 0.0f);
    EXPECT_NEAR(at(2.0f / size), 0.5f, 0.01f);
    EXPECT_NEAR(at(std::pow(2.0f, 0.5f) / size), 0.25f, 0.01f);
    // Beyond the last level: the image's mean.
    EXPECT_NEAR(at(1e6f), 0.5f, 0.01f);
}

// The same checkerboard through the render's texture system (a PNG made by the test): held as
// a MIP map within the limit, grey from afar; at a limit too small for its MIP map it goes to
// OpenImageIO's cache, filtered the same way within its own MIP levels.
TEST(MipPyramid, ImageTexturesHoldImagesAsMipMapsWithinTheLimit) {
    const int size = 512;
    const std::string path = "/tmp/rayo_mip_pyramid_test_" + std::to_string(::getpid()) + ".png";
    {
        auto out = OIIO::ImageOutput::create(path);
        ASSERT_TRUE(out && out->open(path, OIIO::ImageSpec(size, size, 1, OIIO::TypeDesc::UINT8)));
        out->write_image(OIIO::TypeDesc::UINT8, checkerboard(size).data());
        out->close();
    }
    std::ifstream file(path, std::ios::binary);
    std::stringstream bytes;
    bytes << file.rdbuf();
    std::remove(path.c_str());
    auto source = std::make_shared<ImageSource>();
    source->name = "checker.png";
    source->bytes = bytes.str();
    std::vector<Material> materials(1);
    materials[0].images.base.image = source;
    materials[0].images.base.encoding = TextureEncoding::Linear;
    using Slot = ImageTextures::Slot;
    const float s = 100.5f / size, t = 301.5f / size;  // a white texel

    const ImageTextures mipmapped(materials, 8.0f);  // 1.33 MB of MIP map fits
    ImageTextureStats stats = mipmapped.stats();
    EXPECT_EQ(stats.mip_mapped, 1u);
    EXPECT_EQ(stats.memory_used, static_cast<int64_t>(MipPyramid::bytes_for(size, size, false)));
    EXPECT_EQ(mipmapped.lookup(0, Slot::Base, glm::vec2(s, t), 0.0f).x, 1.0f);
    EXPECT_NEAR(mipmapped.lookup(0, Slot::Base, glm::vec2(s, t), 64.0f / size).x, 0.5f, 0.01f);
    // The material's transform scales the footprint: four repeats make each texel a quarter.
    materials[0].images.base.transform = glm::mat3(4.0f, 0, 0, 0, 4.0f, 0, 0, 0, 1);
    const ImageTextures repeated(materials, 8.0f);
    EXPECT_NEAR(repeated.lookup(0, Slot::Base, glm::vec2(s / 4, t / 4), 16.0f / size).x, 0.5f,
                0.01f);
    materials[0].images.base.transform = glm::mat3(1.0f);

    const ImageTextures cached(materials, 1.0f);  // the MIP map is above 1 MB
    EXPECT_NEAR(cached.lookup(0, Slot::Base, glm::vec2(s, t), 0.0f).x, 1.0f, 1e-6f);
    EXPECT_NEAR(cached.lookup(0, Slot::Base, glm::vec2(s, t), 64.0f / size).x, 0.5f, 0.02f);
    stats = cached.stats();
    EXPECT_EQ(stats.mip_mapped, 0u);
    EXPECT_GT(stats.memory_used, 0);  // the tiles the lookups read
}

}  // namespace
}  // namespace rayo
