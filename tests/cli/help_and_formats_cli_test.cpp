// The command line's help (`rayo --help`: the commands and every input format; `rayo COMMAND
// --help`: that command's usage and flags only) and model files in the formats rayo reads itself
// (PLY, STL), rendered directly, described by `rayo info`, and named by a JSON scene.
#include <algorithm>
#include <string>
#include <vector>

#include "tests/cli/cli_fixture.h"

namespace {

using rayo_test::CommandResult;

class HelpCli : public rayo_test::CliFixture {};
class ModelFormatsCli : public rayo_test::CliFixture {};

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST_F(HelpCli, OverviewListsCommandsAndEveryInputFormat) {
    const CommandResult r = run("--help");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* command : {"rayo render", "rayo info", "rayo bench accuracy",
                                "rayo bench suite", "rayo texture", "rayo preview"}) {
        EXPECT_TRUE(contains(r.output, command)) << command << "\n" << r.output;
    }
    for (const char* format : {".json", ".nff", ".obj", ".gltf, .glb", "KHR_draco_mesh_compression",
                               ".ply", ".stl", ".off"}) {
        EXPECT_TRUE(contains(r.output, format)) << format << "\n" << r.output;
    }
    EXPECT_FALSE(contains(r.output, "--max-depth")) << "flags belong to the commands' help";
    // Model files are framed automatically only without a camera of their own (docs/models.md).
    EXPECT_TRUE(contains(r.output, "camera and lights when the file has them")) << r.output;
    EXPECT_TRUE(contains(r.output, "--camera")) << r.output;
    EXPECT_FALSE(contains(r.output, "model files, framed automatically")) << r.output;
}

// Each command's help: exit 0, its own usage line and flags, none of another command's.
TEST_F(HelpCli, EachCommandHasItsOwnHelp) {
    struct Case {
        std::string command;
        std::vector<std::string> own;
        std::string foreign;  // a flag of another command
    };
    const std::vector<Case> cases = {
        {"render",
         {"usage: rayo render", "--max-depth", "--spp", "--view-dir", ".ply"},
         "--over-render"},
        {"info", {"usage: rayo info SCENE", "bounds", ".stl"}, "--spp"},
        {"bench",
         {"usage: rayo bench accuracy", "--only spheres|shapes", "--povray", "--write-nff"},
         "--max-depth"},
        {"texture", {"usage: rayo texture NAME", "--seed", "--scale", "marble"}, "--max-depth"},
        {"preview", {"usage: rayo preview", "--over-render", ".gltf"}, "--spp"},
    };
    for (const Case& c : cases) {
        for (const std::string& flag : {std::string("--help"), std::string("-h")}) {
            const CommandResult r = run(c.command + " " + flag);
            EXPECT_EQ(r.exit_code, 0) << c.command << "\n" << r.output;
            for (const std::string& own : c.own) {
                EXPECT_TRUE(contains(r.output, own)) << c.command << ": " << own << "\n"
                                                     << r.output;
            }
            EXPECT_FALSE(contains(r.output, c.foreign)) << c.command << ": " << c.foreign << "\n"
                                                        << r.output;
        }
    }
    // After other arguments too, and with nothing written.
    const CommandResult r = run("render scene.json -o out.png --help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_TRUE(contains(r.output, "usage: rayo render")) << r.output;
    EXPECT_FALSE(std::filesystem::exists(m_dir / "out.png"));
    // An unknown flag points at the command's own help.
    for (const std::string command : {"render", "preview", "texture marble"}) {
        const CommandResult bad = run(command + " --frobnicate");
        EXPECT_EQ(bad.exit_code, 2) << bad.output;
        EXPECT_TRUE(
            contains(bad.output, "(see rayo " + command.substr(0, command.find(' ')) + " --help)"))
            << bad.output;
    }
}

// An ASCII PLY quad with vertex colours, and the same quad as a binary STL.
const char* const kQuadPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0 255 0 0\n1 0 0 0 255 0\n1 1 0 0 0 255\n0 1 0 255 255 0\n4 0 1 2 3\n";

std::string quad_stl() {
    std::string out(80, ' ');
    const uint32_t count = 2;
    out.append(reinterpret_cast<const char*>(&count), 4);
    const float triangles[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 0},
                                    {0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0}};
    for (const auto& t : triangles) {
        out.append(reinterpret_cast<const char*>(t), sizeof t);
        out.append(2, '\0');
    }
    return out;
}

TEST_F(ModelFormatsCli, PlyAndStlRenderAndDescribe) {
    write("quad.ply", kQuadPly);
    write("quad.stl", quad_stl());
    for (const std::string name : {"quad.ply", "quad.stl"}) {
        const CommandResult info = run("info " + name);
        ASSERT_EQ(info.exit_code, 0) << info.output;
        EXPECT_TRUE(contains(info.output, "triangles 2\n")) << info.output;
        EXPECT_TRUE(contains(info.output, "vertices 4\n")) << info.output;
        EXPECT_TRUE(contains(info.output, "bounds 0 0 0  1 1 0")) << info.output;
        const CommandResult render = run("render " + name + " --width 48 --quiet -o out.exr");
        ASSERT_EQ(render.exit_code, 0) << render.output;
        EXPECT_FALSE(read_pixels("out.exr").empty());
    }
    // The PLY's vertex colours reach the image: the quad's centre mixes two of its corners'
    // colours (red, green, blue, yellow; which two depends on the diagonal), never grey.
    write("scene.json", R"({"rayo": 1, "camera": {"eye": [0.5, 0.5, 2], "look_at": [0.5, 0.5, 0],
        "vfov": 20, "width": 9, "height": 9},
        "lights": [{"type": "directional", "direction": [0, 0, -1]}],
        "objects": [{"type": "mesh", "file": "quad.ply"}]})");
    const CommandResult scene = run("render scene.json --quiet -o scene.exr");
    ASSERT_EQ(scene.exit_code, 0) << scene.output;
    const std::vector<float> rgba = read_pixels("scene.exr");
    ASSERT_EQ(rgba.size(), 9u * 9u * 4u);
    const float* centre = &rgba[(4 * 9 + 4) * 4];
    const float high = std::max({centre[0], centre[1], centre[2]});
    const float low = std::min({centre[0], centre[1], centre[2]});
    EXPECT_GT(high, 0.05f);
    EXPECT_GT(high - low, 0.3f * high) << centre[0] << " " << centre[1] << " " << centre[2];
}

}  // namespace
