// Disks and boxes in JSON scenes through the generic shape reader: fields, defaults, errors at
// their JSON pointers, and a render in which both appear.
#include <gtest/gtest.h>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/error.h"
#include "tests/scene/json_error.h"

namespace rayo {
namespace {

const char* kScene = R"({
  "rayo": 1,
  "camera": {"eye": [0, 2, 8], "look_at": [0, 0, 0], "vfov": 40, "width": 64, "height": 48},
  "materials": {"red": {"kd": [0.8, 0.1, 0.1]}},
  "lights": [{"type": "point", "position": [3, 5, 6]}],
  "objects": [
    {"type": "disk", "center": [0, -1, 0], "radius": 3},
    {"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1], "material": "red"}
  ]
})";

TEST(DiskBoxScene, LoadsWithDefaultsAndRendersBoth) {
    const SceneDescription d = load_json_string(kScene, "s.json", ".");
    ASSERT_EQ(d.scene.shapes.of<Disk>().size(), 1u);
    ASSERT_EQ(d.scene.shapes.of<Box>().size(), 1u);
    EXPECT_EQ(d.scene.shapes.of<Disk>()[0].normal, Vec3(0, 1, 0));  // the default normal
    EXPECT_EQ(d.scene.shapes.of<Box>()[0].max, Vec3(1));
    const RenderResult r = render_scene(d, 2, false);
    // The box's red centre, the grey disk below it on the left, black sky in the corner.
    const Vec3 centre = r.film.rgb(32, 24), floor = r.film.rgb(12, 38);
    EXPECT_GT(centre.x, 2.0f * centre.y);
    EXPECT_GT(floor.y, 0.05f);
    EXPECT_NEAR(floor.x, floor.y, 1e-6f);
    EXPECT_EQ(r.film.rgb(2, 2), Vec3(0.0f));
}

TEST(DiskBoxScene, ErrorsNameTheJsonPointer) {
    auto with_object = [](const std::string& object) {
        return std::string(R"({"rayo": 1, "camera": {"vfov": 40}, "objects": [)") + object + "]}";
    };
    EXPECT_NE(json_error_of(with_object(R"({"type": "disk", "center": [0, 0, 0]})"))
                  .find("s.json#/objects/0/radius: missing required field \"radius\""),
              std::string::npos);
    EXPECT_NE(json_error_of(with_object(R"({"type": "disk", "center": [0,0,0], "radius": 1,
                                       "normal": [0, 0, 0]})"))
                  .find("s.json#/objects/0/normal: expected a non-zero direction"),
              std::string::npos);
    EXPECT_NE(json_error_of(with_object(R"({"type": "box", "min": [0, 0, 0], "max": [1, 0, 1]})"))
                  .find("s.json#/objects/0/max: expected max > min on every axis"),
              std::string::npos);
    EXPECT_NE(json_error_of(with_object(R"({"type": "box", "min": [0, 0, 0], "max": [1, 1, 1],
                                       "radius": 2})"))
                  .find("s.json#/objects/0/radius: unknown key"),
              std::string::npos);
    EXPECT_NE(json_error_of(with_object(R"({"type": "torus"})"))
                  .find("\"box\", \"quadric\", \"ellipsoid\", \"cylinder\", \"paraboloid\", "
                        "\"hyperboloid\", \"blob\", \"csg\", \"triangle\""),
              std::string::npos);
}

}  // namespace
}  // namespace rayo
