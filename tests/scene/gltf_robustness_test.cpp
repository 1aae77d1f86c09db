// glTF files built to break the reader ("Robustness, round three"): an image whose bufferView
// starts or ends past its buffer (a segmentation fault and a heap over-read before), a node chain
// deeper than the stack allows (a segmentation fault before), and a byteStride smaller than the
// element it strides over and a rotation that is no unit quaternion (accepted before). Each is
// refused with the file and the reason.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "apps/scene/mesh_loader.h"
#include "apps/scene/model_scene.h"
#include "core/error.h"
#include "core/scene_limits.h"
#include "tests/scene/gltf_test_writer.h"

namespace rayo {
namespace {

using rayo_test::GltfTestWriter;
using rayo_test::TempDir;

// One triangle with a material, so the file is otherwise valid.
void add_triangle(GltfTestWriter& g) {
    const int position = g.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int mesh = g.mesh({{"attributes", {{"POSITION", position}}}});
    g.node({{"mesh", mesh}});
}

std::string refusal(const std::string& path) {
    try {
        load_model_scene(path, ModelFraming{});
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(GltfRobustness, AnImageBufferViewPastItsBufferIsRefused) {
    TempDir dir;
    for (const bool glb : {false, true}) {
        for (const bool offset : {true, false}) {
            GltfTestWriter g;
            add_triangle(g);
            const unsigned char png_start[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
            const int view = g.view(png_start, sizeof png_start);
            if (offset) {
                g.doc()["bufferViews"][view]["byteOffset"] = 100000000;  // 1e8, far past the end
            } else {
                g.doc()["bufferViews"][view]["byteLength"] = 4096;  // runs past the end
            }
            g.push("images", {{"bufferView", view}, {"mimeType", "image/png"}});
            g.push("textures", {{"source", 0}});
            g.push("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
            g.doc()["meshes"][0]["primitives"][0]["material"] = 0;
            const std::string name =
                std::string(offset ? "offset" : "length") + (glb ? ".glb" : ".gltf");
            const std::string path = glb ? g.write_glb(dir, name) : g.write_embedded(dir, name);
            const std::string message = refusal(path);
            EXPECT_NE(message.find(name + ": image 0: bufferView " + std::to_string(view)),
                      std::string::npos)
                << message;
            EXPECT_NE(message.find("runs past buffer 0"), std::string::npos) << message;
        }
    }
}

TEST(GltfRobustness, ANodeChainDeeperThanTheLimitIsRefusedNotOverflowed) {
    TempDir dir;
    for (const size_t depth : {kMaxGltfNodeDepth, size_t{30000}}) {
        GltfTestWriter g;
        add_triangle(g);  // node 0, a root
        // Node 0's descendants: each the only child of the one before.
        for (size_t i = 1; i < depth; ++i) {
            g.doc()["nodes"][i - 1]["children"] = {static_cast<int>(i)};
            g.node(nlohmann::json::object(), false);
        }
        const std::string path = g.write_embedded(dir, "chain" + std::to_string(depth) + ".gltf");
        const std::string message = refusal(path);
        if (depth <= kMaxGltfNodeDepth) {
            EXPECT_EQ(message, "accepted");
        } else {
            EXPECT_NE(
                message.find("levels deep; the limit is " + std::to_string(kMaxGltfNodeDepth)),
                std::string::npos)
                << message;
        }
    }
}

TEST(GltfRobustness, AStrideShorterThanItsElementIsRefused) {
    TempDir dir;
    GltfTestWriter g;
    add_triangle(g);
    const int view = g.doc()["accessors"][0]["bufferView"];
    g.doc()["bufferViews"][view]["byteStride"] = 4;  // a float VEC3 is 12 bytes
    const std::string message = refusal(g.write_embedded(dir, "stride.gltf"));
    EXPECT_NE(message.find("byteStride 4 (expected a multiple of 4 in [4, 252], at least the 12"),
              std::string::npos)
        << message;
}

// A rotation must be a unit quaternion (glTF 2.0): a zero one cast to the identity and was
// accepted. Within 1e-3 of unit length (exporters round) it is normalised.
TEST(GltfRobustness, ARotationThatIsNotAUnitQuaternionIsRefused) {
    TempDir dir;
    for (const double w : {0.0, 2.0, 1.0005}) {
        GltfTestWriter g;
        add_triangle(g);
        g.doc()["nodes"][0]["rotation"] = {0.0, 0.0, 0.0, w};
        const std::string name = "rotation" + std::to_string(int(w * 10000)) + ".gltf";
        const std::string message = refusal(g.write_embedded(dir, name));
        if (w == 1.0005) {
            EXPECT_EQ(message, "accepted");
        } else {
            EXPECT_NE(message.find(name + ": node 0: rotation (0, 0, 0, " +
                                   (w == 0.0 ? std::string("0") : std::string("2")) +
                                   ") is not a unit quaternion"),
                      std::string::npos)
                << message;
        }
    }
}

// A vertex beyond the number rule is refused with the rule, as PLY, STL and OBJ do (issue 30
// item 13: a vertex at 3e38 gave "no (non-degenerate) triangles").
TEST(GltfRobustness, AVertexBeyondTheNumberRuleIsRefusedWithTheRule) {
    TempDir dir;
    GltfTestWriter g;
    const int position = g.positions({0, 0, 0, 1, 0, 0, 0, 3e38f, 0});
    g.node({{"mesh", g.mesh({{"attributes", {{"POSITION", position}}}})}});
    const std::string message = refusal(g.write_embedded(dir, "far.gltf"));
    EXPECT_NE(message.find("POSITION 2: coordinates must be " + std::string(kSceneMagnitudeRule)),
              std::string::npos)
        << message;
}

// An image the reader refused is named with its reason (issue 30 item 13): a link to /dev/zero
// and an image outside the tree under --restrict-paths were all "not found or unreadable".
TEST(GltfRobustness, AnImageThatCannotBeReadIsNamedWithItsReason) {
    TempDir dir;
    std::filesystem::create_symlink("/dev/zero", dir.file("zero.png"));
    dir.write("../rayo_outside_" + std::to_string(::getpid()) + ".png", "x");
    struct Case {
        std::string uri, reason;
        bool confined;
    };
    const std::vector<Case> cases = {
        {"zero.png", "is a character device; expected a regular file", false},
        {"../rayo_outside_" + std::to_string(::getpid()) + ".png", "outside the scene's directory",
         true},
        {"missing.png", "': not found; shading with the factor", false},
        {"/missing.png", "not found (a glTF image's uri is relative to the file", false},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.uri);
        GltfTestWriter g;
        add_triangle(g);
        g.push("images", {{"uri", c.uri}});
        g.push("textures", {{"source", 0}});
        g.push("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
        g.doc()["meshes"][0]["primitives"][0]["material"] = 0;
        const std::string path = g.write_embedded(dir, "image.gltf");
        const SceneDescription d = load_model_scene(
            path, ModelFraming{}, c.confined ? FileAccess::confined_to_scene(path) : FileAccess());
        std::string warnings;
        for (const std::string& w : d.warnings) warnings += w + "\n";
        EXPECT_NE(warnings.find(c.reason), std::string::npos) << warnings;
    }
    std::filesystem::remove(dir.file("../rayo_outside_" + std::to_string(::getpid()) + ".png"));
}

}  // namespace
}  // namespace rayo
