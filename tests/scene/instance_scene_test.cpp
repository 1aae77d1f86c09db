// Instancing in JSON scenes (docs/scene-format.md, "Groups and instances"): groups and
// instances read, the "sphereflake" generator, errors at their JSON pointers, and a render of a
// group through an identity instance against the same objects placed directly (reflection,
// refraction and shadows through the instance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/error.h"

namespace rayo {
namespace {

const char* kHead = R"("rayo": 1,
  "camera": {"eye": [0, -6, 3], "look_at": [0, 0, 0.5], "up": [0, 0, 1], "vfov": 40,
             "width": 96, "height": 72},
  "materials": {"red": {"kd": [0.8, 0.1, 0.1], "ks": 0.3, "shininess": 20},
                "mirror": {"kd": 0.1, "ks": 0.5, "reflect": 0.8},
                "glass": {"kd": 0, "ks": 0.2, "transmit": 0.9, "ior": 1.5}},
  "lights": [{"type": "point", "position": [3, -4, 6]}])";

const char* kObjects = R"([
    {"type": "sphere", "center": [-1.2, 0, 0.6], "radius": 0.6, "material": "red"},
    {"type": "sphere", "center": [0.2, 0.8, 0.7], "radius": 0.7, "material": "mirror"},
    {"type": "sphere", "center": [0.9, -0.9, 0.5], "radius": 0.5, "material": "glass"},
    {"type": "polygon", "vertices": [[-4, -4, 0], [4, -4, 0], [4, 4, 0], [-4, 4, 0]]}
  ])";

std::string direct_scene() {
    return std::string("{") + kHead + R"(, "objects": )" + kObjects + "}";
}

std::string instanced_scene(const std::string& instance_extra = "") {
    return std::string("{") + kHead + R"(, "groups": {"set": )" + kObjects +
           R"(}, "objects": [{"type": "instance", "of": "set")" + instance_extra + "}]}";
}

SceneDescription load(const std::string& text) {
    return load_json_string(text, "s.json", ".");
}

std::string error_of(const std::string& text) {
    try {
        load(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(InstanceScene, ReadsGroupsAndInstances) {
    const SceneDescription d = load(instanced_scene(
        R"(, "transform": {"translate": [1, 2, 3], "scale": 2}, "material": "red")"));
    ASSERT_EQ(d.scene.groups.size(), 1u);
    EXPECT_EQ(d.scene.groups[0].name, "set");
    EXPECT_EQ(d.scene.groups[0].shapes.of<Sphere>().size(), 3u);
    EXPECT_EQ(d.scene.groups[0].object_count(), 5u);  // 3 spheres, the quad's 2 triangles
    EXPECT_TRUE(d.scene.shapes.of<Sphere>().empty());
    ASSERT_EQ(d.scene.instances.size(), 1u);
    const Instance& i = d.scene.instances[0];
    EXPECT_EQ(i.group, 0u);
    EXPECT_EQ(i.transform[3][0], 1.0f);
    EXPECT_EQ(i.transform[3][2], 3.0f);
    EXPECT_EQ(i.transform[1][1], 2.0f);
    EXPECT_NE(i.material, kNoMaterialOverride);
    EXPECT_EQ(d.scene.instanced_object_count(), 5u);
}

TEST(InstanceScene, MatrixIsReadRowByRow) {
    const SceneDescription d = load(instanced_scene(
        R"(, "transform": {"matrix": [[0, -1, 0, 5], [1, 0, 0, 6], [0, 0, 2, 7]]})"));
    const glm::mat4& m = d.scene.instances[0].transform;
    EXPECT_EQ(m[1][0], -1.0f);  // glm: [column][row]; row 0 = (0, -1, 0, 5)
    EXPECT_EQ(m[0][1], 1.0f);
    EXPECT_EQ(m[3][0], 5.0f);
    EXPECT_EQ(m[3][1], 6.0f);
    EXPECT_EQ(m[2][2], 2.0f);
    EXPECT_EQ(m[3][3], 1.0f);
}

TEST(InstanceScene, SphereflakeObjectGeneratesItsSpheres) {
    const SceneDescription d = load(std::string("{") + kHead +
                                    R"(, "objects": [{"type": "sphereflake", "center": [0, 0, 1],
                                    "radius": 0.5, "depth": 3, "material": "red"}]})");
    const auto& spheres = d.scene.shapes.of<Sphere>();
    ASSERT_EQ(spheres.size(), 1u + 9u + 81u + 729u);
    EXPECT_EQ(spheres[0].center, Vec3(0, 0, 1));
    EXPECT_EQ(spheres[0].radius, 0.5f);
    EXPECT_EQ(spheres[1].radius, 0.5f / 3.0f);
    // Every child touches its parent: the first child sits at distance r + r/3 from the root.
    EXPECT_NEAR(glm::length(spheres[1].center - spheres[0].center), 0.5f + 0.5f / 3.0f, 1e-6f);
}

// The identity instance of the group renders the same image as its objects placed directly,
// to float rounding: t and positions are the same bits, the renormalised normals may differ in
// the last bit (tests/core/instance_test.cpp), and the shading follows.
TEST(InstanceScene, IdentityInstanceRendersAsTheObjectsPlacedDirectly) {
    const RenderResult direct = render_scene(load(direct_scene()), 2, false);
    const RenderResult instanced = render_scene(load(instanced_scene()), 2, false);
    EXPECT_EQ(instanced.instances, 1u);
    EXPECT_EQ(instanced.primitives, direct.primitives);
    float worst = 0.0f;
    for (int y = 0; y < direct.film.height(); ++y) {
        for (int x = 0; x < direct.film.width(); ++x) {
            const Vec3 d = direct.film.rgb(x, y) - instanced.film.rgb(x, y);
            worst =
                std::max(worst, std::max(std::abs(d.x), std::max(std::abs(d.y), std::abs(d.z))));
        }
    }
    EXPECT_LE(worst, 1e-4f);
    // The scene has reflection, refraction and shadows: rays of each kind were traced.
    EXPECT_GT(instanced.counters.reflection, 0u);
    EXPECT_GT(instanced.counters.refraction, 0u);
    EXPECT_GT(instanced.counters.shadow, 0u);
}

TEST(InstanceScene, ErrorsNameTheirPointer) {
    const std::string head = std::string("{") + kHead + ", ";
    const std::string group = R"("groups": {"g": [{"type": "sphere", "center": [0, 0, 0],
                                 "radius": 1}]}, )";
    auto with_instance = [&](const std::string& instance) {
        return head + group + R"("objects": [)" + instance + "]}";
    };
    struct Case {
        std::string text, where, message;
    };
    const Case cases[] = {
        {with_instance(R"({"type": "instance", "of": "h"})"), "s.json#/objects/0/of",
         "unknown group \"h\" (defined in /groups: g)"},
        {with_instance(R"({"type": "instance"})"), "s.json#/objects/0/of", "missing"},
        {with_instance(R"({"type": "instance", "of": 3})"), "s.json#/objects/0/of",
         "expected the name of a group"},
        {with_instance(R"({"type": "instance", "of": "g", "transform": {"scale": [1, 0, 1]}})"),
         "s.json#/objects/0/transform/scale", "non-zero scale"},
        {with_instance(R"({"type": "instance", "of": "g", "transform":
             {"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [1, 1, 0, 0]]}})"),
         "s.json#/objects/0/transform", "singular"},
        {with_instance(R"({"type": "instance", "of": "g", "transform":
             {"matrix": [[1e30, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]}})"),
         "s.json#/objects/0/transform/matrix/0/0", "magnitude <= 1e18"},
        {with_instance(R"({"type": "instance", "of": "g", "transform": {"scale": 1e-20}})"),
         "s.json#/objects/0/transform", "expected an invertible transform"},
        {with_instance(
             R"({"type": "instance", "of": "g", "transform": {"scale": [1e-19, 1e10, 1e9]}})"),
         "s.json#/objects/0/transform", "inverse fit in floats"},
        {with_instance(R"({"type": "instance", "of": "g", "transform":
             {"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]}})"),
         "s.json#/objects/0/transform/matrix/3", "[0, 0, 0, 1]"},
        {with_instance(R"({"type": "instance", "of": "g", "transform":
             {"matrix": [[1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]}})"),
         "s.json#/objects/0/transform/matrix/0", "a row of 4 numbers"},
        {with_instance(R"({"type": "instance", "of": "g", "transform":
             {"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]], "scale": 2}})"),
         "s.json#/objects/0/transform/scale", "unknown"},
        {with_instance(R"({"type": "instance", "of": "g", "material": "none"})"),
         "s.json#/objects/0/material", "unknown material"},
        {head + R"("groups": {"g": [{"type": "instance", "of": "g"}]}})", "s.json#/groups/g/0/type",
         "may not contain instances (of itself"},
        {head + R"("groups": {"g": []}})", "s.json#/groups/g", "non-empty array"},
        {head + R"("groups": [1]})", "s.json#/groups", "expected an object of named groups"},
        {head + R"("groups": {"g": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}]}})",
         "s.json#/groups/g/0/radius", ""},
        {head + R"("objects": [{"type": "sphereflake", "center": [0, 0, 0], "radius": 1,
             "depth": 7}]})",
         "s.json#/objects/0/depth", "expected an integer in [0, 6]"},
        {head + R"("objects": [{"type": "sphereflake", "center": [0, 0, 0], "radius": 0,
             "depth": 2}]})",
         "s.json#/objects/0/radius", "expected a number > 0"},
    };
    for (const Case& c : cases) {
        const std::string error = error_of(c.text);
        EXPECT_EQ(error.rfind(c.where + ":", 0), 0u) << error;
        EXPECT_NE(error.find(c.message), std::string::npos) << error;
    }
}

}  // namespace
}  // namespace rayo
