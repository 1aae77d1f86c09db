// Texture images that declare more pixels than kMaxTexturePixels (shading/image_texture.h) are
// refused from their header, before a pixel is decoded ("Robustness, round three", item 1: a
// 370-byte PNG declaring 100000 × 100000 RGB took 24 GB and 455 s before the kernel killed it).
// The other things a small file can make large (item 11, docs/limits.md "Memory from small
// files"): height images by the floats they decode to, environment images by their pixels, glTF
// files by their nodes.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "apps/scene/environment_image.h"
#include "apps/scene/height_image.h"
#include "apps/scene/json_loader.h"
#include "apps/scene/mesh_loader.h"
#include "core/error.h"
#include "shading/image_texture.h"
#include "tests/scene/header_only_images.h"
#include "tests/scene/scene_test_files.h"

namespace rayo {
namespace {

using rayo_test::png_header_only;

std::string refusal(const rayo_test::TempDir& dir, const std::string& image) {
    const std::string scene = R"({"rayo": 1, "materials": {"default": {"kd": {"image": ")" + image +
                              R"("}}}, "objects": [{"type": "sphere", "center": [0, 0, 0],
                              "radius": 1}]})";
    try {
        load_json_string(scene, "scene.json", dir.path());
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(TextureLimits, AnImageDeclaringMorePixelsThanTheLimitIsRefusedFromItsHeader) {
    rayo_test::TempDir dir;
    dir.write("bomb.png", png_header_only(100000, 100000));
    const std::string message = refusal(dir, "bomb.png");
    EXPECT_NE(message.find("bomb.png' cannot be read: image is 100000x100000; the limit is " +
                           std::to_string(kMaxTexturePixels) + " pixels"),
              std::string::npos)
        << message;
    // Just above the limit is refused too; the header of one at the limit is read (its missing
    // pixel data is the decoder's business, later).
    dir.write("above.png", png_header_only(16384, 16385));
    EXPECT_NE(refusal(dir, "above.png").find("the limit is"), std::string::npos);
    dir.write("at.png", png_header_only(16384, 16384));
    EXPECT_EQ(refusal(dir, "at.png").find("the limit is"), std::string::npos);
}

// A file that is no image and has no image extension (issue 30 item 13: /etc/passwd as a texture
// gave OpenImageIO's 'Image "rayo-image-0" does not exist').
TEST(TextureLimits, AFileThatIsNoImageIsSaidToBeNone) {
    rayo_test::TempDir dir;
    dir.write("passwd", "root:x:0:0:root:/root:/bin/bash\n");
    const std::string message = refusal(dir, "passwd");
    EXPECT_NE(message.find("texture image '" + dir.file("passwd") +
                           "' cannot be read: not an image OpenImageIO can read (no reader "
                           "recognizes its bytes)"),
              std::string::npos)
        << message;
    EXPECT_EQ(message.find("rayo-image"), std::string::npos) << message;
}

// The message of loading `objects` (JSON) with `extra` top-level keys, or "accepted".
std::string scene_refusal(const rayo_test::TempDir& dir, const std::string& objects,
                          const std::string& extra = "") {
    try {
        load_json_string(R"({"rayo": 1, )" + extra + R"("objects": [)" + objects + "]}",
                         "scene.json", dir.path());
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(MemoryFromSmallFiles, HeightImagesAreLimitedByTheFloatsTheyDecodeTo) {
    rayo_test::TempDir dir;
    const auto field = [&](const std::string& name) {
        return scene_refusal(
            dir, R"({"type": "heightfield", "image": ")" + name + R"(", "size": [1, 1, 1]})");
    };
    const std::string grey_most = std::to_string(kMaxHeightSamples);
    const std::string colour_most = std::to_string(kMaxHeightSamples / 3);
    // Grey: kMaxHeightSamples samples; beyond, refused from the header.
    dir.write("grey_above.png", png_header_only(16384, 8193, true));
    EXPECT_NE(
        field("grey_above.png")
            .find("is 16384x8193: expected at least 2x2 and at most " + grey_most + " samples"),
        std::string::npos)
        << field("grey_above.png");
    dir.write("grey_at.png", png_header_only(16384, 8192, true));
    EXPECT_EQ(field("grey_at.png").find("at most"), std::string::npos) << field("grey_at.png");
    // Colour: read as three floats a sample, so a third as many.
    dir.write("colour_above.png", png_header_only(8192, 8192));
    EXPECT_NE(field("colour_above.png")
                  .find("at most " + colour_most +
                        " samples (a colour image; a grey one may have " + grey_most + ")"),
              std::string::npos)
        << field("colour_above.png");
    dir.write("colour_at.png", png_header_only(6688, 6688));  // 44,729,344 samples
    EXPECT_EQ(field("colour_at.png").find("at most"), std::string::npos) << field("colour_at.png");
}

TEST(MemoryFromSmallFiles, EnvironmentImagesAreLimitedByTheirPixels) {
    rayo_test::TempDir dir;
    const auto sky = [&](const std::string& name) {
        return scene_refusal(dir, "", R"("environment": {"image": ")" + name + R"("}, )");
    };
    dir.write("above.png", png_header_only(8194, 4097));
    EXPECT_NE(sky("above.png")
                  .find("is 8194x4097: the limit is " + std::to_string(kMaxEnvironmentPixels) +
                        " pixels"),
              std::string::npos)
        << sky("above.png");
    dir.write("at.png", png_header_only(8192, 4096));
    EXPECT_EQ(sky("at.png").find("the limit is"), std::string::npos) << sky("at.png");
}

TEST(MemoryFromSmallFiles, AGltfFileOfMoreNodesThanTheLimitIsRefusedBeforeTinygltfReadsIt) {
    rayo_test::TempDir dir;
    const auto nodes = [&](size_t count) {
        std::string text = R"({"asset": {"version": "2.0"}, "nodes": [)";
        for (size_t i = 0; i < count; ++i) text += i ? ",{}" : "{}";
        dir.write("nodes.gltf", text + "]}");
        return scene_refusal(dir, R"({"type": "mesh", "file": "nodes.gltf"})");
    };
    const std::string above = nodes(kMaxGltfNodes + 1);
    EXPECT_NE(above.find("nodes.gltf: the file has " + std::to_string(kMaxGltfNodes + 1) +
                         " nodes; the limit is " + std::to_string(kMaxGltfNodes)),
              std::string::npos)
        << above;
    const std::string at = nodes(kMaxGltfNodes);
    EXPECT_EQ(at.find("the limit is"), std::string::npos) << at;
}

}  // namespace
}  // namespace rayo
