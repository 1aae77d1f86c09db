// The `rayo` executable end to end: exit status, error messages that name the place, and no
// output file left behind on failure. Runs the built binary (RAYO_CLI_PATH) in a temp folder.

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli/cli_fixture.h"

namespace fs = std::filesystem;

namespace {

using rayo_test::CommandResult;

class CliTest : public rayo_test::CliFixture {
  protected:
    // Files in the folder other than `keep` (an input the test wrote).
    int count_files_except(const std::string& keep) const {
        int n = 0;
        for (const std::string& name : listing()) n += name != keep;
        return n;
    }
};

const char* const kSmallNff =
    "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 32 24\n"
    "b 0.1 0.2 0.3\nl 3 3 3\nf 1 0 0 0.8 0.2 20 0 1\ns 0 0 0 1\n";

TEST_F(CliTest, RendersDefaultSceneToPng) {
    const CommandResult r = run("render -o out.png --width 80 --height 60");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(fs::exists(m_dir / "out.png"));
    EXPECT_NE(r.output.find("Mrays/s"), std::string::npos) << r.output;  // the summary line
    EXPECT_NE(r.output.find("shadow"), std::string::npos);
}

TEST_F(CliTest, RendersNffToEveryFormat) {
    write("scene.nff", kSmallNff);
    for (const char* out : {"a.exr", "a.png", "a.tif", "a.jpg"}) {
        const CommandResult r = run(std::string("render scene.nff --quiet -o ") + out);
        EXPECT_EQ(r.exit_code, 0) << out << ": " << r.output;
        EXPECT_TRUE(fs::exists(m_dir / out)) << out;
        EXPECT_TRUE(r.output.empty()) << "--quiet printed: " << r.output;
    }
}

TEST_F(CliTest, StatsPrintsTheFullTable) {
    write("scene.nff", kSmallNff);
    const CommandResult r = run("render scene.nff --stats -o s.exr");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    for (const char* row : {"rays camera", "rays shadow", "rays reflection", "rays refraction",
                            "total internal reflections", "paths cut by depth", "time BVH build"}) {
        EXPECT_NE(r.output.find(row), std::string::npos) << row;
    }
    EXPECT_NE(r.output.find("rays camera                 768"), std::string::npos) << r.output;
}

// The example scene's two voxel grids (docs/voxels.md): `rayo info` counts them, the render's
// --stats counts the surface-mode grid as one primitive beside the floor (the composite grid is
// not in the Embree scene).
TEST_F(CliTest, InfoCountsVoxelGrids) {
    const std::string scene = std::string(RAYO_SCENES_DIR) + "/voxels.json";
    const CommandResult info = run("info " + scene);
    EXPECT_EQ(info.exit_code, 0) << info.output;
    EXPECT_NE(info.output.find("voxel_grids 2\n"), std::string::npos) << info.output;
    const CommandResult stats = run("render " + scene + " --width 32 --stats -o v.exr");
    EXPECT_EQ(stats.exit_code, 0) << stats.output;
    EXPECT_NE(stats.output.find("primitives                  2 ("), std::string::npos)
        << stats.output;
}

// A group of a sphere and a triangle placed three times beside a sphere: info and --stats count
// the instances, the primitives stored (the sphere and the group once) and the instanced total
// (docs/scene-format.md, "Groups and instances").
TEST_F(CliTest, InfoAndStatsCountInstances) {
    write("inst.json", R"({"rayo": 1, "camera": {"width": 32, "height": 24, "eye": [0, 0, 9]},
        "groups": {"g": [{"type": "sphere", "center": [0, 0, 0], "radius": 1},
                         {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]},
        "objects": [{"type": "sphere", "center": [0, 3, 0], "radius": 0.5},
                    {"type": "instance", "of": "g"},
                    {"type": "instance", "of": "g", "transform": {"translate": [3, 0, 0]}},
                    {"type": "instance", "of": "g", "transform": {"translate": [-3, 0, 0]}}]})");
    const CommandResult info = run("info inst.json");
    EXPECT_EQ(info.exit_code, 0) << info.output;
    for (const char* row :
         {"spheres 1\n", "groups 1\n", "instances 3\n", "instanced_objects 6\n"}) {
        EXPECT_NE(info.output.find(row), std::string::npos) << row << " in " << info.output;
    }
    const CommandResult stats = run("render inst.json --stats -o s.exr");
    EXPECT_EQ(stats.exit_code, 0) << stats.output;
    EXPECT_NE(stats.output.find("primitives                  7 ("), std::string::npos)
        << stats.output;
    EXPECT_NE(stats.output.find("instances                   3 of 1 group(s): 3 primitives "
                                "stored, 6 objects placed through instances"),
              std::string::npos)
        << stats.output;
}

// --shape-method over the objects' own "method"; --stats prints each type's and object's method
// (docs/shape-methods.md); info counts height fields.
TEST_F(CliTest, ShapeMethodsInStatsAndInfo) {
    write("shapes.json", R"({"rayo": 1, "camera": {"width": 32, "height": 24, "eye": [0, 1, 6]},
        "textures": {"hills": {"type": "perlin"}},
        "objects": [{"type": "cylinder", "base": [-1, -1, 0], "top": [-1, 1, 0], "radius": 0.5},
                    {"type": "cone", "base": [1, -1, 0], "base_radius": 0.5, "apex": [1, 1, 0],
                     "apex_radius": 0,
                     "method": "mesh"},
                    {"type": "heightfield", "texture": "hills", "size": [4, 0.2, 4],
                     "origin": [-2, -2, -2], "method": "dda"}]})");
    const CommandResult info = run("info shapes.json");
    EXPECT_EQ(info.exit_code, 0) << info.output;
    EXPECT_NE(info.output.find("heightfields 1\n"), std::string::npos) << info.output;
    CommandResult r = run("render shapes.json --stats -o s.exr");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("shape method                cone: 1 mesh ("), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("shape method                cone 0 (mesh): mesh, as requested"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("shape method                cylinder"), std::string::npos) << r.output;
    r = run("render shapes.json --stats --shape-method auto -o s.exr");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("shape method                cylinder: 1 mesh ("), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("cone 0 (auto): analytic, analytic: its own intersection"),
              std::string::npos)
        << r.output;
}

TEST_F(CliTest, HelpAndVersion) {
    CommandResult r = run("--help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.output.find("rayo render [SCENE]"), std::string::npos);
    r = run("render --help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.output.find("--max-depth"), std::string::npos);
    r = run("--version");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.output.find("rayo "), std::string::npos);
}

struct BadFlag {
    const char* args;
    const char* message;
};

TEST_F(CliTest, BadFlagsAreRefusedWithoutOutput) {
    const BadFlag cases[] = {
        {"render --frobnicate -o x.png", "unknown option '--frobnicate'"},
        {"render --width abc -o x.png", "--width: expected an integer"},
        {"render --width 0 -o x.png", "--width: expected an integer in [1,"},
        {"render --height -5 -o x.png", "--height: expected an integer"},
        {"render --width 99999999 -o x.png", "--width: expected an integer"},
        {"render --spp 0 -o x.png", "--spp: expected an integer"},
        {"render --threads 0 -o x.png", "--threads: expected an integer"},
        {"render --max-depth 1000 -o x.png", "--max-depth: expected an integer in [0, 64]"},
        {"render --sphere-math fast -o x.png",
         "--sphere-math: expected one of \"stable\", \"seed\", \"double\", got 'fast'"},
        {"render --sphere-method mesh:9 -o x.png",
         "--sphere-method: expected one of \"auto\", \"user\", \"bruteforce\", \"embree-point\", "
         "\"mesh:N\" (N in 0..7), got 'mesh:9'"},
        {"render --sphere-method bvh -o x.png", "got 'bvh'"},
        {"render --max-error-px 0 -o x.png", "--max-error-px: expected a number in [1e-06"},
        {"render --max-error-px nan -o x.png", "--max-error-px: expected a number in"},
        {"render --max-error-px 2x -o x.png", "--max-error-px: expected a number in"},
        {"render --shape-method fast -o x.png",
         "--shape-method: expected one of \"analytic\", \"mesh\", \"auto\", got 'fast'"},
        {"render --range log -o x.png",
         "--range: expected one of \"clamp\", \"normalize\", got 'log'"},
        {"render -o", "-o: missing value"},
        {"render a.nff b.nff -o x.png", "unexpected argument 'b.nff'"},
        {"explode", "unknown command 'explode'"},
    };
    for (const BadFlag& c : cases) {
        const CommandResult r = run(c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << " -> " << r.output;
        EXPECT_EQ(count_files_except(""), 0) << c.args;
    }
}

TEST_F(CliTest, MissingSceneFileNamesIt) {
    const CommandResult r = run("render nowhere.nff -o x.png");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("nowhere.nff"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(m_dir / "x.png"));
}

TEST_F(CliTest, UnknownSceneExtension) {
    write("scene.txt", kSmallNff);
    const CommandResult r = run("render scene.txt -o x.png");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("scene.txt: unknown scene format"), std::string::npos) << r.output;
    EXPECT_EQ(count_files_except("scene.txt"), 0);
}

// A tetrahedron model with its material library.
const char* const kTetraObj =
    "mtllib tetra.mtl\nusemtl red\nv 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 2\n"
    "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
const char* const kTetraMtl = "newmtl red\nKd 0.9 0.1 0.1\n";

TEST_F(CliTest, ModelFileRendersFramedWithNoSceneFile) {
    write("tetra.obj", kTetraObj);
    write("tetra.mtl", kTetraMtl);
    const CommandResult r = run("render tetra.obj --width 64 -o tetra.exr");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // The model is in the picture: its red material lights pixels near the image centre
    // (and the centre itself shows the model, not the ground or the background).
    const std::vector<float> rgba = read_pixels("tetra.exr");
    ASSERT_EQ(rgba.size(), 64u * 48u * 4u);
    const size_t centre = (24u * 64u + 32u) * 4u;
    EXPECT_GT(rgba[centre], 2.0f * rgba[centre + 1])
        << "R " << rgba[centre] << " G " << rgba[centre + 1];

    const CommandResult info = run("info tetra.obj");
    ASSERT_EQ(info.exit_code, 0) << info.output;
    EXPECT_NE(info.output.find("triangles 4\n"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("vertices 4\n"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("bounds 0 0 0  2 2 2\n"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("lights 2\n"), std::string::npos) << info.output;

    // Without its material library the model still renders, in the default material, with
    // a warning that names the library.
    fs::remove(m_dir / "tetra.mtl");
    const CommandResult bare = run("render tetra.obj --width 32 -o bare.png");
    EXPECT_EQ(bare.exit_code, 0) << bare.output;
    EXPECT_NE(bare.output.find("warning: "), std::string::npos) << bare.output;
    EXPECT_NE(bare.output.find("material library 'tetra.mtl' not found"), std::string::npos)
        << bare.output;

    // Framing flags are for model files: a warning elsewhere.
    write("scene.nff", kSmallNff);
    const CommandResult warned = run("render scene.nff --no-ground --width 16 -o s.png");
    EXPECT_EQ(warned.exit_code, 0) << warned.output;
    EXPECT_NE(warned.output.find("apply to model files only"), std::string::npos) << warned.output;
}

// A glTF quad (data-URI buffer) with two cameras and a spot light (docs/models.md).
const char* const kCameraGltf = R"({"asset": {"version": "2.0"}, "scene": 0,
 "scenes": [{"nodes": [0, 1, 2, 3]}],
 "nodes": [{"mesh": 0}, {"camera": 0, "name": "front", "translation": [0, 0, 3]},
           {"camera": 1, "translation": [0, 0, 4]},
           {"translation": [0, 0, 2], "extensions": {"KHR_lights_punctual": {"light": 0}}}],
 "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "aspectRatio": 1.5, "znear": 0.1}},
             {"name": "top", "type": "orthographic",
              "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}}],
 "extensionsUsed": ["KHR_lights_punctual"],
 "extensions": {"KHR_lights_punctual": {"lights": [{"name": "lamp", "type": "spot",
   "intensity": 6.283185307179586, "spot": {"outerConeAngle": 0.5}}]}},
 "meshes": [{"primitives": [{"attributes": {"POSITION": 1}, "indices": 0}]}],
 "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAACAPwAAgD8AAAAAAACAvwAAgD8AAAAAAAABAAIAAAACAAMA"}],
 "bufferViews": [{"buffer": 0, "byteOffset": 48, "byteLength": 12},
                 {"buffer": 0, "byteOffset": 0, "byteLength": 48}],
 "accessors": [{"bufferView": 0, "componentType": 5123, "count": 6, "type": "SCALAR"},
               {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3",
                "min": [-1, -1, 0], "max": [1, 1, 0]}]})";

TEST_F(CliTest, ModelCamerasAndLightsAreListedAndChosen) {
    write("cams.gltf", kCameraGltf);
    const CommandResult info = run("info cams.gltf");
    EXPECT_EQ(info.exit_code, 0) << info.output;
    EXPECT_NE(info.output.find("resolution 720x480"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("camera 0 'front' perspective position 0 0 3 direction 0 0 -1 "
                               "yfov 45.8366 degrees aspect 1.5"),
              std::string::npos)
        << info.output;
    EXPECT_NE(info.output.find("camera 1 'top' orthographic position 0 0 4"), std::string::npos)
        << info.output;
    // The spot light, intensity 2π cd → 2 (I/π); no automatic key and fill.
    EXPECT_NE(info.output.find("light 0 'lamp' spot position 0 0 2 direction 0 0 -1 cone 0-28.6479 "
                               "degrees color 1 1 1 intensity 2\n"),
              std::string::npos)
        << info.output;
    EXPECT_EQ(info.output.find("'key'"), std::string::npos) << info.output;

    const CommandResult by_name = run("render cams.gltf --camera top --width 24 -o top.png");
    EXPECT_EQ(by_name.exit_code, 0) << by_name.output;
    EXPECT_NE(by_name.output.find("camera 'top' is orthographic"), std::string::npos)
        << by_name.output;
    const CommandResult by_index = run("render cams.gltf --camera 0 --width 24 -o front.png");
    EXPECT_EQ(by_index.exit_code, 0) << by_index.output;
    EXPECT_NE(by_index.output.find("24x16"), std::string::npos) << by_index.output;
    const CommandResult unknown = run("render cams.gltf --camera 5 --width 24 -o x.png");
    EXPECT_EQ(unknown.exit_code, 1);
    EXPECT_NE(unknown.output.find("cams.gltf: --camera: no camera '5'; the file's cameras are: 0 "
                                  "'front', 1 'top', or \"auto\""),
              std::string::npos)
        << unknown.output;
}

// The bounds `rayo info` prints are the ones the framing uses: with the objects that instances
// place (a glTF mesh two nodes use, one of them far from the origin; a JSON group), not only
// the objects placed directly.
TEST_F(CliTest, InfoBoundsIncludeInstances) {
    std::string gltf = kCameraGltf;
    const std::string nodes = R"("nodes": [{"mesh": 0}, {"camera": 0, "name": "front")";
    ASSERT_NE(gltf.find(nodes), std::string::npos);
    gltf.replace(gltf.find(nodes), nodes.size(),
                 R"("nodes": [{"mesh": 0, "children": [4]}, {"camera": 0, "name": "front")");
    const std::string last = R"("extensions": {"KHR_lights_punctual": {"light": 0}}}],)";
    ASSERT_NE(gltf.find(last), std::string::npos);
    gltf.replace(gltf.find(last), last.size(),
                 R"("extensions": {"KHR_lights_punctual": {"light": 0}}},
           {"mesh": 0, "translation": [100, 20, -30]}],)");
    write("far.gltf", gltf);
    const CommandResult far = run("info far.gltf");
    ASSERT_EQ(far.exit_code, 0) << far.output;
    EXPECT_NE(far.output.find("instances 2\n"), std::string::npos) << far.output;
    EXPECT_NE(far.output.find("bounds -1 -1 -30  101 21 0\n"), std::string::npos) << far.output;

    write("inst.json", R"({"rayo": 1, "camera": {"width": 32, "height": 24, "eye": [0, 0, 9]},
        "groups": {"g": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]},
        "objects": [{"type": "sphere", "center": [0, 3, 0], "radius": 0.5},
                    {"type": "instance", "of": "g", "transform": {"translate": [-3, 0, 0]}},
                    {"type": "instance", "of": "g", "transform": {"translate": [10, 0, 0]}}]})");
    const CommandResult json = run("info inst.json");
    ASSERT_EQ(json.exit_code, 0) << json.output;
    EXPECT_NE(json.output.find("bounds -4 -1 -1  11 3.5 1\n"), std::string::npos) << json.output;
}

TEST_F(CliTest, UnwritableOutputLeavesNothing) {
    write("scene.nff", kSmallNff);
    CommandResult r = run("render scene.nff -o no/such/dir/x.png");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("no/such/dir/x.png"), std::string::npos) << r.output;
    r = run("render scene.nff -o x.bmpx");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("x.bmpx"), std::string::npos) << r.output;
    EXPECT_EQ(count_files_except("scene.nff"), 0);
}

TEST_F(CliTest, UnknownViewIsRefusedAndLeavesNothing) {
    write("scene.nff", kSmallNff);
    const CommandResult r = run("render scene.nff --view Nope -o x.png");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("Nope"), std::string::npos) << r.output;
    EXPECT_EQ(count_files_except("scene.nff"), 0);
}

TEST_F(CliTest, DegenerateCamerasAreRefusedWithTheirLine) {
    struct Case {
        const char* view;
        const char* message;
    };
    const Case cases[] = {
        {"from 0 0 0\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0\nresolution 8 8\n", "look_at"},
        {"from 0 0 5\nat 0 0 0\nup 0 0 1\nangle 40\nhither 0\nresolution 8 8\n", "parallel"},
        {"from 0 0 5\nat 0 0 0\nup 0 1 0\nangle 180\nhither 0\nresolution 8 8\n", "(0, 180)"},
        {"from 0 0 5\nat 0 0 0\nup 0 1 0\nangle 0\nhither 0\nresolution 8 8\n", "(0, 180)"},
    };
    for (const Case& c : cases) {
        write("bad.nff", std::string("v\n") + c.view + "f 1 1 1 1 0 1 0 1\ns 0 0 0 1\n");
        const CommandResult r = run("render bad.nff -o x.png");
        EXPECT_EQ(r.exit_code, 1) << c.view;
        EXPECT_NE(r.output.find("bad.nff:1"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(m_dir / "x.png"));
    }
}

TEST_F(CliTest, EverySphereMethodRendersAndStatsSayWhichRan) {
    write("scene.nff", kSmallNff);
    for (const char* method : {"bruteforce", "user", "embree-point", "mesh:2"}) {
        const CommandResult r =
            run(std::string("render scene.nff --stats -o m.exr --sphere-method ") + method);
        EXPECT_EQ(r.exit_code, 0) << method << ": " << r.output;
        EXPECT_NE(r.output.find(std::string("sphere method               ") + method),
                  std::string::npos)
            << r.output;
    }
    const CommandResult r = run("render scene.nff --stats -o m.exr --sphere-math double");
    EXPECT_NE(r.output.find("user (double)"), std::string::npos) << r.output;
    const CommandResult a = run("render scene.nff --stats -o m.exr");
    EXPECT_NE(a.output.find("user (stable): user/stable: analytic"), std::string::npos) << a.output;
}

TEST_F(CliTest, WidthAloneKeepsAspectRatio) {
    write("scene.nff", kSmallNff);  // 32x24
    const CommandResult r = run("render scene.nff --width 64 --stats -o x.exr");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("64x48"), std::string::npos) << r.output;
}

TEST_F(CliTest, AntialiasingFlagsOverrideTheScene) {
    write("scene.nff", kSmallNff);  // 32x24, one tile: adaptive traces at least the 33x25 corners
    const CommandResult r =
        run("render scene.nff --stats -o a.exr --aa adaptive --aa-threshold 0.05 --aa-depth 2");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("antialiasing                adaptive, threshold 0.05, depth 2"),
              std::string::npos)
        << r.output;
    const size_t at = r.output.find("rays camera");
    ASSERT_NE(at, std::string::npos) << r.output;
    EXPECT_GT(std::stoull(r.output.substr(at + 12)), 33u * 25u) << r.output;
    // The stratified default, and back to it from a scene that asks for adaptive.
    const CommandResult s = run("render scene.nff --stats -o s.exr --spp 4 --aa stratified");
    EXPECT_NE(s.output.find("antialiasing                stratified, 4 spp"), std::string::npos)
        << s.output;
    EXPECT_NE(s.output.find("rays camera                 3072"), std::string::npos) << s.output;
}

}  // namespace
