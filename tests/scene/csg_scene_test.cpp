// CSG in JSON scenes (core/shapes/csg.h): the tree read from "children", the object's material,
// renders in which a CSG equal to a sphere (the sphere intersected with a box around it) looks
// like the sphere — opaque with its shadow, and as refracting glass — and bad trees refused at
// their JSON pointers.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/error.h"
#include "tests/scene/json_error.h"

namespace rayo {
namespace {

const std::string kSphere = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})";
const std::string kBox = R"({"type": "box", "min": [0, 0, 0], "max": [1, 1, 1]})";

std::string with_object(const std::string& object) {
    return std::string(R"({"rayo": 1, "camera": {"vfov": 40},
        "materials": {"red": {"kd": [0.8, 0.1, 0.1]}}, "objects": [)") +
           object + "]}";
}

TEST(CsgScene, ReadsANestedTreeWithTheObjectsMaterial) {
    const std::string inner =
        R"({"type": "csg", "op": "intersection", "children": [)" + kSphere + ", " + kBox + "]}";
    const std::string middle =
        R"({"type": "csg", "op": "union", "children": [)" + inner + ", " + kSphere + "]}";
    const SceneDescription d = load_json_string(
        with_object(R"({"type": "csg", "op": "difference", "material": "red", "children": [)" +
                    middle + ", " + kBox + "]}"),
        "s.json", ".");
    const std::vector<Csg>& csgs = d.scene.shapes.of<Csg>();
    ASSERT_EQ(csgs.size(), 1u);
    EXPECT_EQ(csgs[0].leaves.size(), 4u);
    EXPECT_EQ(csgs[0].nodes.size(), 7u);
    EXPECT_EQ(csgs[0].nodes.back().op, CsgOp::Difference);
    EXPECT_EQ(csgs[0].material, 1u);                   // "red", after "default"
    EXPECT_TRUE(d.scene.shapes.of<Sphere>().empty());  // the children are not scene objects
}

TEST(CsgScene, BadTreesAreRefusedAtTheirPointer) {
    auto expect_error = [&](const std::string& object, const std::string& message) {
        const std::string error = json_error_of(with_object(object));
        EXPECT_NE(error.find(message), std::string::npos) << error;
    };
    expect_error(R"({"type": "csg", "op": "union", "children": []})",
                 "s.json#/objects/0/children: expected an array of 2 closed shapes, got");
    expect_error(R"({"type": "csg", "op": "union", "children": [)" + kSphere + "]}",
                 "s.json#/objects/0/children: expected an array of 2 closed shapes, got");
    expect_error(R"({"type": "csg", "op": "xor", "children": [)" + kSphere + ", " + kBox + "]}",
                 "s.json#/objects/0/op: expected one of \"union\", \"intersection\", "
                 "\"difference\", got the string \"xor\"");
    expect_error(R"({"type": "csg", "children": [)" + kSphere + ", " + kBox + "]}",
                 "s.json#/objects/0/op: missing required field \"op\"");
    expect_error(R"({"type": "csg", "op": "union", "children": [)" + kSphere +
                     R"(, {"type": "disk", "center": [0, 0, 0], "radius": 1}]})",
                 "s.json#/objects/0/children/1: expected a closed shape (a solid) as a CSG "
                 "child, got an open disk");
    expect_error(R"({"type": "csg", "op": "union", "children": [)" + kSphere +
                     R"(, {"type": "cylinder", "base": [0, 0, 0], "top": [0, 1, 0], "radius": 1,
                           "capped": false}]})",
                 "s.json#/objects/0/children/1: expected a closed shape (a solid) as a CSG "
                 "child, got an open cylinder");
    expect_error(R"({"type": "csg", "op": "union", "children": [)" + kSphere +
                     R"(, {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]})",
                 "s.json#/objects/0/children/1/type: expected one of");
    expect_error(R"({"type": "csg", "op": "union", "children": [)" + kSphere +
                     R"(, {"type": "sphere", "center": [0, 0, 0], "radius": -1}]})",
                 "s.json#/objects/0/children/1/radius: expected a number > 0");
    expect_error(
        R"({"type": "csg", "op": "union", "children": [)" + kSphere +
            R"(, {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "red"}]})",
        "s.json#/objects/0/children/1/material: a CSG child takes the material of its "
        "CSG object");
    expect_error(R"({"type": "csg", "op": "union", "children": [)" + kSphere + ", 3]}",
                 "s.json#/objects/0/children/1: expected a closed shape, got");
    // Nine operations deep (the limit is eight).
    std::string deep = kSphere;
    for (int i = 0; i < kMaxCsgDepth + 1; ++i) {
        deep = R"({"type": "csg", "op": "union", "children": [)" + kSphere + ", " + deep + "]}";
    }
    std::string where = "s.json#/objects/0";
    for (int i = 0; i < kMaxCsgDepth; ++i) where += "/children/1";
    expect_error(deep, where + ": expected CSG nested at most 8 deep");
    // Eight deep is fine.
    std::string eight = kSphere;
    for (int i = 0; i < kMaxCsgDepth; ++i) {
        eight = R"({"type": "csg", "op": "union", "children": [)" + kSphere + ", " + eight + "]}";
    }
    EXPECT_EQ(json_error_of(with_object(eight)), "no error");
    // More leaves than the crossing budget: 32 quadrics × 4 crossings fit, the 33rd does not.
    std::string wide = kSphere;
    for (int i = 0; i < 5; ++i) {
        wide = R"({"type": "csg", "op": "union", "children": [)" + wide + ", " + wide + "]}";
    }
    EXPECT_EQ(json_error_of(with_object(wide)), "no error");  // 32 leaves
    expect_error(R"({"type": "csg", "op": "union", "children": [)" + wide + ", " + kSphere + "]}",
                 "s.json#/objects/0/children/1: expected a CSG whose children cross a line at "
                 "most 128 times in all");
}

// A sphere, or the same sphere as a CSG (intersected with a box around it): on a striped wall
// and a floor, under a point light. The images agree up to the hit positions' rounding (the
// sphere projects its hits onto itself, CSG keeps the ray's point).
std::string scene_with(const std::string& material, bool as_csg) {
    const std::string sphere = R"({"type": "sphere", "center": [-0.3, 0.2, 0], "radius": 1.1)";
    const std::string object =
        as_csg ? R"({"type": "csg", "op": "intersection", "material": ")" + material +
                     R"(", "children": [)" + sphere +
                     R"(}, {"type": "box", "min": [-2, -2, -2], "max": [2, 2, 2]}]})"
               : sphere + R"(, "material": ")" + material + "\"}";
    return R"({"rayo": 1,
      "camera": {"eye": [0, 0.5, 7], "look_at": [0, 0, 0], "vfov": 40, "width": 80, "height": 60},
      "render": {"max_depth": 8}, "background": 0.1, "ambient_light": 0.3,
      "materials": {
        "glass": {"kd": 0, "ka": 0, "ks": 0.6, "shininess": 300, "reflect": 0.08,
                  "transmit": 0.9, "ior": 1.5},
        "plastic": {"kd": [0.2, 0.7, 0.3], "ks": 0.3, "shininess": 40},
        "white": {"kd": 0.8}, "red": {"kd": [0.8, 0.1, 0.1]}},
      "lights": [{"type": "point", "position": [2, 5, 6]}],
      "objects": [
        {"type": "polygon", "vertices": [[-6, -3, -3], [6, -3, -3], [6, 4, -3], [-6, 4, -3]],
         "material": "white"},
        {"type": "polygon", "vertices": [[-6, -1, -2.9], [6, -1, -2.9], [6, 0, -2.9], [-6, 0, -2.9]],
         "material": "red"},
        {"type": "polygon", "vertices": [[-6, -1.2, -3], [6, -1.2, -3], [6, -1.2, 4], [-6, -1.2, 4]],
         "material": "white"},
        )" +
           object + "]}";
}

void expect_same_image(const std::string& material) {
    const RenderResult sphere =
        render_scene(load_json_string(scene_with(material, false), "s.json", "."), 2, false);
    const RenderResult csg =
        render_scene(load_json_string(scene_with(material, true), "c.json", "."), 2, false);
    const auto& a = sphere.film.rgba();
    const auto& b = csg.film.rgba();
    ASSERT_EQ(a.size(), b.size());
    double sum = 0.0;
    int far_off = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        const double diff = std::abs(a[i] - b[i]);
        sum += diff;
        if (diff > 0.02) ++far_off;
    }
    // (Measured: a mean difference of 1e-9 opaque, 4e-9 glass, no pixel off by 0.02.) A pixel
    // or two may differ where a refracted ray grazes an edge of the stripes.
    EXPECT_LT(sum / a.size(), 1e-6) << material;
    EXPECT_LE(far_off, 2) << material;
    // And the object is there: the centre of the image is not the background.
    EXPECT_NE(csg.film.rgb(36, 28), Vec3(0.1f)) << material;
}

TEST(CsgScene, OpaqueCsgSphereShadesAndShadowsLikeTheSphere) {
    expect_same_image("plastic");
}

TEST(CsgScene, GlassCsgSphereRefractsLikeTheSphere) {
    expect_same_image("glass");
}

}  // namespace
}  // namespace rayo
