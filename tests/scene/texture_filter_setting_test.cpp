// The image textures' filter setting (render.texture_filter; shading/mip_pyramid.h): bilinear
// by default, bicubic when asked, anything else refused at its JSON pointer.
#include <gtest/gtest.h>

#include <string>

#include "apps/scene/json_loader.h"
#include "core/error.h"

namespace rayo {
namespace {

TEST(TextureFilterSetting, BilinearByDefaultAndBicubicWhenAsked) {
    EXPECT_EQ(load_json_string(R"({"rayo": 1})", "scene.json", ".").settings.texture_filter,
              TextureFilter::Bilinear);
    EXPECT_EQ(load_json_string(R"({"rayo": 1, "render": {"texture_filter": "bilinear"}})",
                               "scene.json", ".")
                  .settings.texture_filter,
              TextureFilter::Bilinear);
    EXPECT_EQ(load_json_string(R"({"rayo": 1, "render": {"texture_filter": "bicubic"}})",
                               "scene.json", ".")
                  .settings.texture_filter,
              TextureFilter::Bicubic);
}

TEST(TextureFilterSetting, AnythingElseIsRefusedAtItsPointer) {
    for (const std::string value : {"\"trilinear\"", "\"Bicubic\"", "1", "true", "null"}) {
        try {
            load_json_string(R"({"rayo": 1, "render": {"texture_filter": )" + value + "}}",
                             "scene.json", ".");
            ADD_FAILURE() << value << " accepted";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("scene.json#/render/texture_filter"), std::string::npos)
                << message;
            EXPECT_NE(message.find("\"bilinear\", \"bicubic\""), std::string::npos) << message;
        }
    }
}

}  // namespace
}  // namespace rayo
