// Blobs in JSON scenes (core/shapes/blob.h): elements read as records through the generic
// field reader, a render in which the blob appears, a blob as a CSG child, and bad values
// refused at their JSON pointers.
#include <gtest/gtest.h>

#include "apps/scene/json_loader.h"
#include "apps/scene/renderer.h"
#include "core/error.h"
#include "tests/scene/json_error.h"

namespace rayo {
namespace {

std::string with_object(const std::string& object) {
    return std::string(R"({"rayo": 1,
      "camera": {"eye": [0, 0, 6], "look_at": [0, 0, 0], "vfov": 40, "width": 64, "height": 48},
      "materials": {"red": {"kd": [0.8, 0.1, 0.1]}},
      "lights": [{"type": "point", "position": [3, 5, 6]}], "objects": [)") +
           object + "]}";
}

const char* kBlob = R"({"type": "blob", "threshold": 0.5, "material": "red", "elements": [
    {"center": [-0.6, 0, 0], "radius": 1, "strength": 1},
    {"center": [0.6, 0, 0], "radius": 1, "strength": 1},
    {"center": [0, 0.5, 0], "radius": 0.4, "strength": -0.5}]})";

TEST(BlobScene, ReadsElementsAndRenders) {
    const SceneDescription d = load_json_string(with_object(kBlob), "s.json", ".");
    const std::vector<Blob>& blobs = d.scene.shapes.of<Blob>();
    ASSERT_EQ(blobs.size(), 1u);
    ASSERT_EQ(blobs[0].elements.size(), 3u);
    EXPECT_EQ(blobs[0].elements[2].strength, -0.5f);
    EXPECT_EQ(blobs[0].elements[1].center, Vec3(0.6f, 0.0f, 0.0f));
    EXPECT_EQ(blobs[0].threshold, 0.5f);
    EXPECT_EQ(blobs[0].material, 1u);
    const RenderResult r = render_scene(d, 2, false);
    const Vec3 centre = r.film.rgb(26, 24);  // the left element
    EXPECT_GT(centre.x, 2.0f * centre.y);
    EXPECT_EQ(r.film.rgb(1, 1), Vec3(0.0f));
}

TEST(BlobScene, IsACsgChild) {
    const std::string csg = std::string(R"({"type": "csg", "op": "difference", "children": [)") +
                            R"({"type": "blob", "threshold": 0.5, "elements": [
                                 {"center": [0, 0, 0], "radius": 1, "strength": 1}]},
                               {"type": "box", "min": [0, -2, -2], "max": [2, 2, 2]}]})";
    const SceneDescription d = load_json_string(with_object(csg), "s.json", ".");
    ASSERT_EQ(d.scene.shapes.of<Csg>().size(), 1u);
    EXPECT_EQ(d.scene.shapes.of<Csg>()[0].leaf_budget(), 2 + kMaxShapeCrossings);
}

TEST(BlobScene, BadValuesAreRefusedAtTheirPointer) {
    auto expect_error = [&](const std::string& object, const std::string& message) {
        const std::string error = json_error_of(with_object(object));
        EXPECT_NE(error.find(message), std::string::npos) << error;
    };
    expect_error(R"({"type": "blob", "threshold": 0.5, "elements": []})",
                 "s.json#/objects/0/elements: expected at least one element");
    expect_error(R"({"type": "blob", "threshold": 0.5})",
                 "s.json#/objects/0/elements: missing required field \"elements\"");
    expect_error(R"({"type": "blob", "threshold": 0.5, "elements": 3})",
                 "s.json#/objects/0/elements: expected an array of objects, got");
    expect_error(R"({"type": "blob", "threshold": 0.5, "elements": [3]})",
                 "s.json#/objects/0/elements/0: expected an object, got");
    expect_error(R"({"type": "blob", "threshold": 0.5, "elements": [
                     {"center": [0, 0, 0], "radius": -1, "strength": 1}]})",
                 "s.json#/objects/0/elements/0/radius: expected a number > 0");
    expect_error(R"({"type": "blob", "threshold": 0.5, "elements": [
                     {"center": [0, 0, 0], "radius": 1}]})",
                 "s.json#/objects/0/elements/0/strength: missing required field \"strength\"");
    expect_error(R"({"type": "blob", "threshold": 0.5, "elements": [
                     {"center": [0, 0, 0], "radius": 1, "strength": 1, "size": 2}]})",
                 "s.json#/objects/0/elements/0/size: unknown");
    expect_error(R"({"type": "blob", "threshold": 0, "elements": [
                     {"center": [0, 0, 0], "radius": 1, "strength": 1}]})",
                 "s.json#/objects/0/threshold: expected a number > 0");
    expect_error(R"({"type": "blob", "threshold": 2, "elements": [
                     {"center": [0, 0, 0], "radius": 1, "strength": 1},
                     {"center": [1, 0, 0], "radius": 1, "strength": -1}]})",
                 "s.json#/objects/0/threshold: expected a threshold below the sum of the "
                 "positive strengths");
    std::string many = R"({"type": "blob", "threshold": 0.5, "elements": [)";
    for (int i = 0; i <= kMaxBlobElements; ++i) {
        many += std::string(i ? ", " : "") + R"({"center": [0, 0, 0], "radius": 1, "strength": 1})";
    }
    expect_error(many + "]}", "s.json#/objects/0/elements: expected at most 128 elements");
}

}  // namespace
}  // namespace rayo
