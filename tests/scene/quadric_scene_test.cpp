// Quadrics in JSON scenes through the generic shape reader: the general quadric's coefficients
// and bounds, the named forms' fields and defaults, errors at their JSON pointers, and a render
// in which they appear.
#include <gtest/gtest.h>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/error.h"
#include "tests/scene/json_error.h"

namespace rayo {
namespace {

const char* kScene = R"({
  "rayo": 1,
  "camera": {"eye": [0, 1, 8], "look_at": [0, 0, 0], "vfov": 40, "width": 64, "height": 48},
  "materials": {"red": {"kd": [0.8, 0.1, 0.1]}},
  "lights": [{"type": "point", "position": [3, 5, 6]}],
  "objects": [
    {"type": "quadric", "coefficients": [1, 1, 1, 0, 0, 0, 0, 0, 0, -1],
     "bounds": {"min": [-2, -2, -2], "max": [2, 2, 0.5]}, "material": "red"},
    {"type": "ellipsoid", "center": [3, 0, 0], "radii": [1, 0.5, 0.5]},
    {"type": "cylinder", "base": [-3, -1, 0], "top": [-3, 1, 0], "radius": 0.5},
    {"type": "paraboloid", "vertex": [0, 2, 0], "radius": 1, "height": 1, "capped": false},
    {"type": "hyperboloid", "center": [0, -2, 0], "axis": [1, 0, 0], "radius": 0.3,
     "semi_axis": 0.5, "height": 2, "sheets": 2}
  ]
})";

TEST(QuadricScene, LoadsFieldsWithDefaultsAndRenders) {
    const SceneDescription d = load_json_string(kScene, "s.json", ".");
    const Shapes& shapes = d.scene.shapes;
    ASSERT_EQ(shapes.of<Quadric>().size(), 1u);
    EXPECT_EQ(shapes.of<Quadric>()[0].coefficients[9], -1.0f);
    EXPECT_EQ(shapes.of<Quadric>()[0].clip.upper, Vec3(2.0f, 2.0f, 0.5f));
    EXPECT_TRUE(shapes.of<Quadric>()[0].capped);
    ASSERT_EQ(shapes.of<Ellipsoid>().size(), 1u);
    EXPECT_EQ(shapes.of<Ellipsoid>()[0].radii, Vec3(1.0f, 0.5f, 0.5f));
    ASSERT_EQ(shapes.of<Cylinder>().size(), 1u);
    EXPECT_TRUE(shapes.of<Cylinder>()[0].capped);
    ASSERT_EQ(shapes.of<Paraboloid>().size(), 1u);
    EXPECT_FALSE(shapes.of<Paraboloid>()[0].capped);
    EXPECT_EQ(shapes.of<Paraboloid>()[0].axis, Vec3(0, 1, 0));  // the default axis
    ASSERT_EQ(shapes.of<Hyperboloid>().size(), 1u);
    EXPECT_EQ(shapes.of<Hyperboloid>()[0].sheets, 2);
    EXPECT_EQ(shapes.of<Hyperboloid>()[0].axis, Vec3(1, 0, 0));
    const RenderResult r = render_scene(d, 2, false);
    // The red clipped sphere in the centre, black sky in the corner.
    const Vec3 centre = r.film.rgb(32, 24);
    EXPECT_GT(centre.x, 2.0f * centre.y);
    EXPECT_EQ(r.film.rgb(1, 1), Vec3(0.0f));
}

TEST(QuadricScene, ErrorsNameTheJsonPointer) {
    auto with_object = [](const std::string& object) {
        return std::string(R"({"rayo": 1, "camera": {"vfov": 40}, "objects": [)") + object + "]}";
    };
    auto expect_error = [&](const std::string& object, const std::string& message) {
        const std::string error = json_error_of(with_object(object));
        EXPECT_NE(error.find(message), std::string::npos) << error;
    };
    const std::string sphere = R"("coefficients": [1, 1, 1, 0, 0, 0, 0, 0, 0, -1])";
    expect_error(R"({"type": "quadric", )" + sphere + "}",
                 "s.json#/objects/0/bounds: missing required field \"bounds\"");
    expect_error(
        R"({"type": "quadric", )" + sphere + R"(, "bounds": {"min": [0, 0, 0], "max": [1, 0, 1]}})",
        "s.json#/objects/0/bounds/max: expected max > min on every axis");
    expect_error(
        R"({"type": "quadric", )" + sphere + R"(, "bounds": {"min": [2, 2, 2], "max": [1, 1, 1]}})",
        "s.json#/objects/0/bounds/max: expected max > min on every axis");
    expect_error(R"({"type": "quadric", )" + sphere + R"(, "bounds": {"min": [0, 0, 0]}})",
                 "s.json#/objects/0/bounds/max: missing required field \"max\"");
    expect_error(R"({"type": "quadric", )" + sphere + R"(, "bounds": [0, 1]})",
                 "s.json#/objects/0/bounds: expected {\"min\"");
    expect_error(R"({"type": "quadric", "coefficients": [0, 0, 0, 0, 0, 0, 0, 0, 0, 1],
                     "bounds": {"min": [0, 0, 0], "max": [1, 1, 1]}})",
                 "s.json#/objects/0/coefficients: expected a non-zero quadratic or linear part");
    expect_error(R"({"type": "quadric", "coefficients": [1, 1, 1],
                     "bounds": {"min": [0, 0, 0], "max": [1, 1, 1]}})",
                 "s.json#/objects/0/coefficients: expected an array of 10 numbers");
    expect_error(R"({"type": "quadric", "coefficients": [1, 1, 1, 0, 1e300, 0, 0, 0, 0, -1],
                     "bounds": {"min": [0, 0, 0], "max": [1, 1, 1]}})",
                 "s.json#/objects/0/coefficients/4: expected");
    expect_error(R"({"type": "quadric", "coefficients": [1, 1, 1, 0, 0, 0, 0, 0, 0, "x"],
                     "bounds": {"min": [0, 0, 0], "max": [1, 1, 1]}})",
                 "s.json#/objects/0/coefficients/9: expected a number");
    expect_error(R"({"type": "ellipsoid", "center": [0, 0, 0], "radii": [1, -1, 1]})",
                 "s.json#/objects/0/radii: expected three numbers > 0");
    expect_error(R"({"type": "cylinder", "base": [0, 0, 0], "top": [0, 0, 0], "radius": 1})",
                 "s.json#/objects/0/top: expected top != base");
    expect_error(R"({"type": "cylinder", "base": [0, 0, 0], "top": [0, 1, 0], "radius": 1,
                     "capped": 1})",
                 "s.json#/objects/0/capped: expected true or false");
    expect_error(R"({"type": "paraboloid", "vertex": [0, 0, 0], "radius": 1, "height": 0})",
                 "s.json#/objects/0/height: expected a number > 0");
    expect_error(R"({"type": "hyperboloid", "center": [0, 0, 0], "radius": 1, "semi_axis": 1,
                     "height": 2, "sheets": 3})",
                 "s.json#/objects/0/sheets: expected 1 or 2");
    expect_error(R"({"type": "hyperboloid", "center": [0, 0, 0], "radius": 1, "semi_axis": 1,
                     "height": 2, "sheets": 1.5})",
                 "s.json#/objects/0/sheets: expected an integer");
    expect_error(R"({"type": "hyperboloid", "center": [0, 0, 0], "radius": 1, "semi_axis": 1,
                     "height": 2, "sheets": 2})",
                 "s.json#/objects/0/height: expected height > 2 * semi_axis");
}

}  // namespace
}  // namespace rayo
