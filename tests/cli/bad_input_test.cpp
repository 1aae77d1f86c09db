// The catalogue of bad input, end to end through the `rayo` executable (RAYO_CLI_PATH):
// every case must exit non-zero, print "rayo: error: <place>: <what was expected>" with the place
// as file:line (NFF, OBJ), file:line:column (JSON syntax) or file#/json/pointer, and leave no
// file behind (no image, no temporary). The loaders' own tests (nff_loader_test.cpp,
// json_loader_test.cpp, mesh_loader_test.cpp) check the messages in detail; cli_test.cpp covers
// the flags and NFF cameras; this file covers each kind of bad input for each format at the CLI.

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "tests/cli/cli_fixture.h"

namespace fs = std::filesystem;

namespace {

using rayo_test::CommandResult;

// One bad input: the file's text, the place the error must name and what it must say.
struct BadCase {
    std::string label;
    std::string text;
    std::string place;
    std::string expected;
};

class BadInput : public rayo_test::CliFixture {
  protected:
    // Copies a file of tests/data/bad/ into the test's folder.
    void copy_data(const std::string& name) {
        fs::copy_file(fs::path(RAYO_TEST_DATA_DIR) / "bad" / name, m_dir / name,
                      fs::copy_options::overwrite_existing);
    }

    // Runs `args`, expects exit status `exit_code`, "rayo: error: " followed by the place, the
    // expected text, and the folder exactly as it was before (nothing written).
    void expect_refused(const std::string& args, const std::string& place,
                        const std::string& expected, const std::string& label, int exit_code = 1) {
        const std::set<std::string> before = listing();
        const CommandResult r = run(args);
        EXPECT_EQ(r.exit_code, exit_code) << label << ": " << args << "\n" << r.output;
        EXPECT_NE(r.output.find("rayo: error: " + place), std::string::npos)
            << label << ": the message does not start with the place '" << place << "':\n"
            << r.output;
        EXPECT_NE(r.output.find(expected), std::string::npos)
            << label << ": the message does not say '" << expected << "':\n"
            << r.output;
        EXPECT_EQ(listing(), before) << label << ": files were left behind";
    }

    // Writes each case as `scene_name` and renders it.
    void expect_cases_refused(const std::string& scene_name, const std::vector<BadCase>& cases) {
        for (const BadCase& c : cases) {
            write(scene_name, c.text);
            expect_refused("render " + scene_name + " -o out.png", c.place, c.expected, c.label);
            fs::remove(m_dir / scene_name);
        }
    }
};

class BadInputNff : public BadInput {};
class BadInputJson : public BadInput {};
class BadInputObj : public BadInput {};
class BadInputGltf : public BadInput {};
class BadInputPlyStl : public BadInput {};
class BadInputCli : public BadInput {};

// ---- NFF ----------------------------------------------------------------------------------

// A valid NFF view block (lines 1-7) and material (line 8): line 9 is the first object line.
const std::string kView =
    "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 32 24\n"
    "f 1 0 0 0.8 0.2 20 0 1\n";

std::string view_with(const std::string& resolution) {
    return "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution " + resolution +
           "\ns 0 0 0 1\n";
}

TEST_F(BadInputNff, TruncatedAndBinaryFiles) {
    copy_data("truncated.nff");  // ends inside the third vertex of a 4-vertex polygon
    expect_refused("render truncated.nff -o out.png", "truncated.nff:12", "expects 3 numbers",
                   "truncated polygon");
    copy_data("binary.nff");  // a PNG header
    expect_refused("render binary.nff -o out.png", "binary.nff:1", "not an NFF text file",
                   "binary file");
    expect_cases_refused(
        "bad.nff",
        {
            {"view block cut short", "v\nfrom 0 0 5\nat 0 0", "bad.nff:3", "'at' expects 3"},
            {"polygon cut short", kView + "p 5\n0 0 0\n1 0 0\n1 1 0\n", "bad.nff:9",
             "polygon declares 5 vertices, the file ends after 3"},
            {"empty file", "", "bad.nff:1", "no viewpoint"},
            {"NUL byte", kView + std::string("s 0 0\0 0 1\n", 11), "bad.nff:9", "NUL byte"},
        });
}

TEST_F(BadInputNff, UnknownEntitiesAndWrongArgumentCounts) {
    expect_cases_refused(
        "bad.nff",
        {
            {"unknown entity", kView + "torus 0 0 0 1 2\n", "bad.nff:9", "'torus'"},
            {"sphere with 3 numbers", kView + "s 0 0 1\n", "bad.nff:9", "'s' expects 4 numbers"},
            {"sphere with 5 numbers", kView + "s 0 0 0 1 1\n", "bad.nff:9", "'s' expects 4"},
            {"light with 4 numbers", kView + "l 1 2 3 4\n", "bad.nff:9", "'l' expects 3"},
            {"material with 7 numbers", kView + "f 1 1 1 1 0 1 0\n", "bad.nff:9",
             "'f' expects 8 numbers"},
            {"polygon vertex with 4 numbers", kView + "p 3\n0 0 0\n1 0 0 7\n0 1 0\n", "bad.nff:11",
             "expects 3 numbers"},
        });
}

TEST_F(BadInputNff, NanInfiniteAndAbsurdMagnitudes) {
    expect_cases_refused(
        "bad.nff",
        {
            {"NaN radius", kView + "s 0 0 0 nan\n", "bad.nff:9", "expected a finite number"},
            {"infinite light", kView + "l inf 0 0\n", "bad.nff:9", "expected a finite number"},
            {"NaN vertex", kView + "p 3\n0 0 0\n1 NaN 0\n0 1 0\n", "bad.nff:11",
             "expected a finite number"},
            {"radius overflows float", kView + "s 0 0 0 1e39\n", "bad.nff:9",
             "expected a finite number (in float range)"},
            {"radius whose square overflows float", kView + "s 0 0 0 1e30\n", "bad.nff:9",
             "of magnitude <= 1e18"},
            {"radius overflows double", kView + "s 0 0 0 1e999\n", "bad.nff:9", "out of range"},
            {"infinite angle", "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle inf\n", "bad.nff:5",
             "expected a finite number"},
        });
}

TEST_F(BadInputNff, ZeroAndAbsurdResolutions) {
    expect_cases_refused(
        "bad.nff",
        {
            {"zero width", view_with("0 24"), "bad.nff:7", "resolution must be positive"},
            {"negative height", view_with("32 -24"), "bad.nff:7", "resolution must be positive"},
            {"side over the limit", view_with("70000 30"), "bad.nff:7", "at most 65536"},
            {"fractional", view_with("32.5 24"), "bad.nff:7", "expected an integer"},
            {"one number", view_with("32"), "bad.nff:7", "'resolution' expects 2 integers"},
        });
}

TEST_F(BadInputNff, DegeneratePolygons) {
    expect_cases_refused(
        "bad.nff",
        {
            {"two vertices", kView + "p 2\n0 0 0\n1 0 0\n", "bad.nff:9", "at least 3 vertices"},
            {"collinear", kView + "p 3\n0 0 0\n1 1 1\n2 2 2\n", "bad.nff:9", "degenerate polygon"},
            {"zero patch normal", kView + "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 0\n0 1 0 0 0 1\n",
             "bad.nff:11", "vertex normal has zero length"},
            {"degenerate cone", kView + "c 1 2 3 1 1 2 3 0.5\n", "bad.nff:9", "zero length"},
        });
}

// ---- JSON ---------------------------------------------------------------------------------

std::string with_object(const std::string& object) {
    return "{\"rayo\": 1, \"objects\": [" + object + "]}";
}

std::string with_camera(const std::string& camera) {
    return "{\"rayo\": 1, \"camera\": {" + camera + "}}";
}

TEST_F(BadInputJson, TruncatedAndBinaryFiles) {
    copy_data("truncated.json");  // ends inside a key on line 4
    expect_refused("render truncated.json -o out.png", "truncated.json:4:", "missing closing quote",
                   "truncated file");
    copy_data("binary.json");
    expect_refused("render binary.json -o out.png", "binary.json:1:1", "invalid JSON",
                   "binary file");
    copy_data("utf16.json");  // UTF-16 with a byte-order mark: JSON must be UTF-8
    expect_refused("render utf16.json -o out.png", "utf16.json:1:1", "invalid JSON", "UTF-16 file");
    expect_cases_refused("bad.json", {
                                         {"empty file", "", "bad.json:1:1", "invalid JSON"},
                                         {"unclosed array", "{\"rayo\": 1, \"objects\": [\n",
                                          "bad.json:2:1", "invalid JSON"},
                                     });
}

TEST_F(BadInputJson, UnknownEntitiesAndWrongArgumentCounts) {
    expect_cases_refused(
        "bad.json",
        {
            {"unknown object type", with_object(R"({"type": "torus"})"), "bad.json#/objects/0/type",
             "expected one of"},
            {"unknown light type", R"({"rayo": 1, "lights": [{"type": "laser"}]})",
             "bad.json#/lights/0/type",
             "expected one of \"point\", \"directional\", \"area\", \"spot\""},
            {"spot cone wider than a hemisphere",
             R"({"rayo": 1, "lights": [{"type": "spot", "position": [0, 1, 0],
                 "direction": [0, -1, 0], "outer_cone_angle": 120}]})",
             "bad.json#/lights/0/outer_cone_angle", "expected an angle in degrees in (0, 90]"},
            {"spot inner cone not inside the outer",
             R"({"rayo": 1, "lights": [{"type": "spot", "position": [0, 1, 0],
                 "direction": [0, -1, 0], "inner_cone_angle": 30, "outer_cone_angle": 20}]})",
             "bad.json#/lights/0/inner_cone_angle", "below outer_cone_angle"},
            {"spot without a direction",
             R"({"rayo": 1, "lights": [{"type": "spot", "position": [0, 1, 0]}]})",
             "bad.json#/lights/0", "direction"},
            {"unknown key", R"({"rayo": 1, "camara": {}})", "bad.json#/camara",
             "unknown key \"camara\""},
            {"centre with 2 numbers", with_object(R"({"type": "sphere", "center": [0, 0],
                                                    "radius": 1})"),
             "bad.json#/objects/0/center", "expected an array of 3 numbers"},
            {"centre with 4 numbers", with_object(R"({"type": "sphere", "center": [0, 0, 0, 0],
                                                    "radius": 1})"),
             "bad.json#/objects/0/center", "got an array of 4"},
            {"triangle with 4 vertices",
             with_object(R"({"type": "triangle", "vertices": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]]})"),
             "bad.json#/objects/0/vertices", "expected an array of 3 vertices"},
            {"cone without apex radius",
             with_object(R"({"type": "cone", "base": [0,0,0], "apex": [0,1,0], "base_radius": 1})"),
             "bad.json#/objects/0/apex_radius", "missing required field \"apex_radius\""},
        });
}

TEST_F(BadInputJson, NanInfiniteAndAbsurdMagnitudes) {
    expect_cases_refused(
        "bad.json",
        {
            {"NaN literal", R"({"rayo": 1, "background": NaN})", "bad.json:1:", "invalid literal"},
            {"Infinity literal", R"({"rayo": 1, "ambient_light": Infinity})",
             "bad.json:1:", "invalid literal"},
            {"number overflows double", "{\"rayo\": 1,\n \"background\": 1e999}", "bad.json:2:16",
             "1e999"},
            {"radius overflows float",
             with_object(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1e39})"),
             "bad.json#/objects/0/radius", "fits a float"},
            {"radius whose square overflows float",
             with_object(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1e30})"),
             "bad.json#/objects/0/radius", "magnitude <= 1e18"},
            {"centre overflows float",
             with_object(R"({"type": "sphere", "center": [0, -4e38, 0], "radius": 1})"),
             "bad.json#/objects/0/center/1", "fits a float"},
        });
}

// Nesting beyond 256 levels is refused at the first bracket too deep, whatever the depth: at
// 100,000 levels nlohmann's recursive dump() (once used to quote the value) overflowed the stack.
TEST_F(BadInputJson, NestingDeeperThanTheLimit) {
    auto nested = [](const std::string& open, const std::string& close, int depth) {
        std::string text;
        for (int i = 0; i < depth; ++i) text += open;
        for (int i = 0; i < depth; ++i) text += close;
        return text;
    };
    const std::string deep_objects = "{\"rayo\": 1, \"objects\": " + nested("[", "]", 100000) + "}";
    const std::string top_level = nested("[", "]", 100000);
    const std::string comment_then_deep =
        "// [[[[ a comment\n{\"a\": " + nested("[", "]", 300) + "}";
    expect_cases_refused(
        "bad.json",
        {
            // The first "[" (column 24) is level 2, so level 257 is the 256th "[": column 279.
            {"100,000 levels under objects", deep_objects, "bad.json:1:279",
             "nested deeper than 256 levels"},
            {"100,000 levels at the top", top_level, "bad.json:1:257",
             "nested deeper than 256 levels"},
            {"brackets in a comment do not count", comment_then_deep, "bad.json:2:262",
             "nested deeper than 256 levels"},
        });
    // 256 levels are JSON the parser takes (the scene is then refused for its content instead).
    write("ok_depth.json", "{\"rayo\": 1, \"x\": " + nested("[", "]", 255) + "}");
    const CommandResult r = run("render ok_depth.json -o out.png");
    EXPECT_EQ(r.output.find("nested deeper"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("unknown key \"x\""), std::string::npos) << r.output;
}

TEST_F(BadInputJson, DegenerateCameras) {
    expect_cases_refused(
        "bad.json",
        {
            {"eye = look_at", with_camera(R"("eye": [1, 2, 3], "look_at": [1, 2, 3])"),
             "bad.json#/camera/look_at", "differ from eye"},
            {"up parallel to view", with_camera(R"("eye": [0, 5, 0], "look_at": [0, 0, 0])"),
             "bad.json#/camera", "parallel"},
            {"zero up", with_camera(R"("up": [0, 0, 0])"), "bad.json#/camera", "up"},
            {"hfov 0", with_camera(R"("hfov": 0)"), "bad.json#/camera/hfov", "expected a number"},
            {"vfov 180", with_camera(R"("vfov": 180)"), "bad.json#/camera/vfov", "(0, 180)"},
            {"hfov 270", with_camera(R"("hfov": 270)"), "bad.json#/camera/hfov", "(0, 180)"},
            {"distance 0", with_camera(R"("distance": 0)"), "bad.json#/camera/distance",
             "expected a number > 0"},
        });
}

TEST_F(BadInputJson, ZeroAndAbsurdResolutions) {
    expect_cases_refused(
        "bad.json", {
                        {"zero width", with_camera(R"("width": 0)"), "bad.json#/camera/width",
                         "expected an integer in [1, 65536]"},
                        {"zero height", with_camera(R"("height": 0)"), "bad.json#/camera/height",
                         "expected an integer in [1, 65536]"},
                        {"side over the limit", with_camera(R"("width": 70000)"),
                         "bad.json#/camera/width", "expected an integer in [1, 65536], got 70000"},
                        {"fractional width", with_camera(R"("width": 64.5)"),
                         "bad.json#/camera/width", "expected an integer"},
                        {"width over int", with_camera(R"("width": 1e12)"),
                         "bad.json#/camera/width", "expected an integer"},
                    });
}

TEST_F(BadInputJson, DegeneratePolygons) {
    expect_cases_refused(
        "bad.json",
        {
            {"two vertices", with_object(R"({"type": "polygon", "vertices": [[0,0,0],[1,0,0]]})"),
             "bad.json#/objects/0/vertices", "at least 3 vertices"},
            {"collinear polygon",
             with_object(R"({"type": "polygon", "vertices": [[0,0,0],[1,1,1],[2,2,2],[3,3,3]]})"),
             "bad.json#/objects/0/vertices", "non-zero area"},
            {"collinear triangle",
             with_object(R"({"type": "triangle", "vertices": [[0,0,0],[1,0,0],[2,0,0]]})"),
             "bad.json#/objects/0/vertices", "non-zero area"},
        });
}

TEST_F(BadInputJson, DegenerateQuadrics) {
    const std::string box = R"("bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]})";
    expect_cases_refused(
        "bad.json",
        {
            {"no quadratic or linear part",
             with_object(R"({"type": "quadric", "coefficients": [0,0,0,0,0,0,0,0,0,-1], )" + box +
                         "}"),
             "bad.json#/objects/0/coefficients", "non-zero quadratic or linear part"},
            {"coefficient beyond the scene magnitude",
             with_object(R"({"type": "quadric", "coefficients": [1,1,1,0,0,0,0,0,0,-1e20], )" +
                         box + "}"),
             "bad.json#/objects/0/coefficients/9", "magnitude <= 1e18"},
            {"inverted bounds",
             with_object(R"({"type": "quadric", "coefficients": [1,1,1,0,0,0,0,0,0,-1],
                             "bounds": {"min": [1, 1, 1], "max": [-1, -1, -1]}})"),
             "bad.json#/objects/0/bounds/max", "expected max > min on every axis"},
            {"missing bounds",
             with_object(R"({"type": "quadric", "coefficients": [1,1,1,0,0,0,0,0,0,-1]})"),
             "bad.json#/objects/0/bounds", "missing required field \"bounds\""},
            {"cylinder of zero length",
             with_object(R"({"type": "cylinder", "base": [0,0,0], "top": [0,0,0], "radius": 1})"),
             "bad.json#/objects/0/top", "expected top != base"},
        });
}

TEST_F(BadInputJson, MissingMeshFiles) {
    expect_cases_refused(
        "bad.json",
        {
            {"missing obj", with_object(R"({"type": "mesh", "file": "none.obj"})"),
             "bad.json#/objects/0/file",
             "cannot open mesh file 'none.obj': No such file or directory"},
            {"missing glb in a folder", with_object(R"({"type": "mesh", "file": "no/none.glb"})"),
             "bad.json#/objects/0/file", "'no/none.glb'"},
            {"unknown mesh format", with_object(R"({"type": "mesh", "file": "a.fbx"})"),
             "bad.json#/objects/0/file", ".obj, .gltf, .glb, .ply, .stl or .off"},
            {"folder as mesh", with_object(R"({"type": "mesh", "file": "."})"),
             "bad.json#/objects/0/file", ".obj, .gltf, .glb, .ply, .stl or .off"},
        });
}

TEST_F(BadInputJson, VoxelFilesAndValues) {
    write("v.raw", std::string(8, '\x80'));  // 2 × 2 × 2 u8 voxels
    const auto voxels = [](const std::string& fields) {
        return with_object(R"({"type": "voxels", "file": "v.raw", "size": [1, 1, 1], )" + fields +
                           "}");
    };
    expect_cases_refused(
        "bad.json",
        {
            {"dims not matching the file", voxels(R"("dims": [2, 2, 3])"),
             "bad.json#/objects/0/dims", "2 × 2 × 3 u8 voxels are 12 bytes, the file has 8"},
            {"format not matching the file", voxels(R"("dims": [2, 2, 2], "format": "f32")"),
             "bad.json#/objects/0/dims", "2 × 2 × 2 f32 voxels are 32 bytes, the file has 8"},
            {"missing voxel file",
             with_object(R"({"type": "voxels", "file": "none.raw", "dims": [2, 2, 2],
                             "size": [1, 1, 1]})"),
             "bad.json#/objects/0/file",
             "cannot open voxel file 'none.raw': No such file or directory"},
            {"dims below 2", voxels(R"("dims": [1, 2, 4])"), "bad.json#/objects/0/dims/0",
             "expected an integer in [2, 65536], got 1"},
            {"negative size", with_object(R"({"type": "voxels", "file": "v.raw", "dims": [2, 2, 2],
                             "size": [1, 1, -2]})"),
             "bad.json#/objects/0/size/2", "expected a number > 0, got -2"},
            {"unknown mode", voxels(R"("dims": [2, 2, 2], "mode": "mip")"),
             "bad.json#/objects/0/mode", "expected one of \"surface\", \"composite\""},
            {"unsorted transfer", voxels(R"("dims": [2, 2, 2], "mode": "composite",
                       "transfer": [{"value": 1, "color": 1, "density": 1},
                                    {"value": 0, "color": 1, "density": 1}])"),
             "bad.json#/objects/0/transfer/1/value", "expected stops sorted by value"},
        });
}

// ---- OBJ (through a JSON scene that references m.obj) ---------------------------------------

const std::string kObjScene = with_object(R"({"type": "mesh", "file": "m.obj"})");

TEST_F(BadInputObj, TruncatedAndBinaryFiles) {
    write("scene.json", kObjScene);
    copy_data("binary.obj");
    fs::rename(m_dir / "binary.obj", m_dir / "m.obj");
    expect_refused("render scene.json -o out.png", "m.obj:2", "not an OBJ text file", "binary obj");
    fs::remove(m_dir / "m.obj");
    const std::vector<BadCase> cases = {
        {"cut inside a vertex", "v 0 0 0\nv 1 0 0\nv 0 1", "m.obj:3", "'v' expects 3 numbers"},
        {"cut inside a face", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2", "m.obj:4", "at least 3 vertices"},
        {"empty", "", "scene.json#/objects/0/file", "no (non-degenerate) triangles"},
    };
    for (const BadCase& c : cases) {
        write("m.obj", c.text);
        expect_refused("render scene.json -o out.png", c.place, c.expected, c.label);
    }
}

TEST_F(BadInputObj, WrongCountsNanInfiniteAndAbsurdValues) {
    write("scene.json", kObjScene);
    const std::string tail = "v 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::vector<BadCase> cases = {
        {"vertex with 2 numbers", "v 0 0\n" + tail, "m.obj:1", "'v' expects 3 numbers"},
        {"vertex with a word", "v 0 zero 0\n" + tail, "m.obj:1", "got 'zero'"},
        {"NaN vertex", "v 0 0 nan\n" + tail, "m.obj:1", "expected a finite number"},
        {"infinite vertex", "v 0 0 inf\n" + tail, "m.obj:1", "expected a finite number"},
        {"vertex overflows float", "v 0 0 1e39\n" + tail, "m.obj:1",
         "expected a finite number (in float range)"},
        {"normal with 2 numbers", "v 0 0 0\n" + tail + "vn 0 1\n", "m.obj:5",
         "'vn' expects 3 numbers"},
        {"face index past the end", "v 0 0 0\n" + tail + "f 1 2 9\n", "m.obj:5",
         "face index out of bounds"},
    };
    for (const BadCase& c : cases) {
        write("m.obj", c.text);
        expect_refused("render scene.json -o out.png", c.place, c.expected, c.label);
    }
}

TEST_F(BadInputObj, DegenerateFacesAndMissingMaterials) {
    write("scene.json", kObjScene);
    const std::vector<BadCase> cases = {
        {"two-vertex face", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", "m.obj:4", "at least 3 vertices"},
        {"only collinear faces", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n",
         "scene.json#/objects/0/file", "no (non-degenerate) triangles"},
        {"unknown material", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl nope\nf 1 2 3\n", "m.obj",
         "'nope'"},
    };
    for (const BadCase& c : cases) {
        write("m.obj", c.text);
        expect_refused("render scene.json -o out.png", c.place, c.expected, c.label);
    }
    // A transform that pushes the mesh past the scene magnitude (1e18, core/scene_limits.h).
    write("m.obj", "v 1000 0 0\nv 0 1000 0\nv 0 0 1000\nf 1 2 3\n");
    write("big.json",
          with_object(R"({"type": "mesh", "file": "m.obj", "transform": {"scale": 1e17}})"));
    expect_refused("render big.json -o out.png", "big.json#/objects/0/transform",
                   "does not fit in floats", "transform overflow");
}

// ---- glTF (through a JSON scene that references m.gltf) -------------------------------------

TEST_F(BadInputGltf, TruncatedFileAndMissingBuffer) {
    write("scene.json", with_object(R"({"type": "mesh", "file": "m.gltf"})"));
    write("m.gltf", R"({"asset": {"version": "2.0"}, "meshes": [)");
    expect_refused("render scene.json -o out.png", "m.gltf", "malformed glTF", "truncated gltf");
    write("m.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "none.bin",
                       "byteLength": 44}]})");
    expect_refused("render scene.json -o out.png", "m.gltf", "none.bin", "missing buffer");
    write("scene.json", with_object(R"({"type": "mesh", "file": "m.glb"})"));
    copy_data("binary.obj");  // not glTF's binary container
    fs::rename(m_dir / "binary.obj", m_dir / "m.glb");
    expect_refused("render scene.json -o out.png", "m.glb", "glTF", "not a glb");
}

// ---- PLY and STL (rayo's readers), directly and through a JSON scene -------------------------

TEST_F(BadInputPlyStl, TruncatedOutOfRangeAndEmptyFiles) {
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    write("cut.ply", header + "0 0 0\n1 0");
    expect_refused("render cut.ply -o out.png", "cut.ply:3", "PLY element 'vertex' declares 3",
                   "truncated ply");
    expect_refused("info cut.ply", "cut.ply:3", "truncated file?", "truncated ply, info");
    write("far.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n");
    expect_refused("render far.ply -o out.png", "far.ply", "vertex index 5 out of range",
                   "face index out of range");
    write("empty.stl", "");
    expect_refused("render empty.stl -o out.png", "empty.stl", "empty STL", "empty stl");
    write("scene.json", with_object(R"({"type": "mesh", "file": "far.ply"})"));
    expect_refused("render scene.json -o out.png", "far.ply", "out of range", "ply in a scene");
}

// ---- the command line -----------------------------------------------------------------------

const char* const kGoodNff =
    "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 32 24\n"
    "l 3 3 3\nf 1 0 0 0.8 0.2 20 0 1\ns 0 0 0 1\n";

TEST_F(BadInputCli, UnwritableOutputs) {
    write("scene.nff", kGoodNff);
    fs::create_directories(m_dir / "folder.png");
    expect_refused("render scene.nff -o folder.png", "folder.png", "cannot write",
                   "output is a folder");
    expect_refused("render scene.nff -o scene.nff/x.png", "scene.nff/x.png", "cannot write",
                   "parent is a file");
    expect_refused("render scene.nff -o /proc/rayo_bad_input.exr", "/proc/rayo_bad_input.exr",
                   "cannot write", "read-only file system");
    expect_refused("render scene.nff -o out", "out", "", "no extension");
    write("scene.json", "{\"rayo\": 1}");
    expect_refused("render scene.json -o no/such/dir/x.exr", "no/such/dir/x.exr", "cannot write",
                   "json scene, missing folder");
}

// Output problems are found before the render, not after it: a render that would take minutes
// (4096², 4096 samples per pixel of the built-in scene) is refused at once, with nothing written.
TEST_F(BadInputCli, OutputProblemsAreFoundBeforeRendering) {
    fs::create_directories(m_dir / "folder.png");
    const std::string long_name(300, 'n');
    struct Case {
        std::string output, extra, place, expected;
    };
    const Case cases[] = {
        {"x.bmpx", "", "x.bmpx", "unsupported image extension '.bmpx'"},
        {"no/such/dir/x.exr", "", "no/such/dir/x.exr",
         "the directory 'no/such/dir' does not exist"},
        {"folder.png", "", "folder.png", "cannot write: it is a directory"},
        {"x.png", "--view Nope", "x.png", "unknown OCIO view 'Nope'"},
        {long_name + ".png", "", long_name + ".png",
         "the file name is 304 bytes; the file system allows at most 255"},
    };
    for (const Case& c : cases) {
        const auto start = std::chrono::steady_clock::now();
        expect_refused(
            "render --width 4096 --height 4096 --spp 4096 --quiet -o " + c.output + " " + c.extra,
            c.place, c.expected, c.output);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_LT(seconds, 30.0) << c.output << ": the render ran before the output was checked";
    }
}

// A legal name of 250 bytes is written, although ".NAME.tmpPID.png" would not fit in 255: the
// temporary name is shortened instead.
TEST_F(BadInputCli, LongLegalOutputNamesAreWritten) {
    const std::string name = std::string(246, 'n') + ".png";
    const CommandResult r = run("render --width 16 --height 12 --quiet -o " + name);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(listing(), std::set<std::string>{name});
}

TEST_F(BadInputCli, FlagValuesCliTestDoesNotCover) {
    write("scene.nff", kGoodNff);
    struct Flag {
        const char* args;
        const char* expected;
    };
    const Flag flags[] = {
        {"--tile-size 0", "--tile-size: expected an integer in [16, 4096], got '0'"},
        {"--tile-size 5000", "--tile-size: expected an integer in [16, 4096]"},
        {"--tile-size 24", "--tile-size: expected a multiple of 16 in [16, 4096], got 24"},
        {"--threads 5000", "--threads: expected an integer in [1, 4096]"},
        {"--spp 70000", "--spp: expected an integer in [1, 65536]"},
        {"--max-depth -1", "--max-depth: expected an integer in [0, 64], got '-1'"},
        {"--max-depth 65", "--max-depth: expected an integer in [0, 64], got '65'"},
        {"--width 12px", "--width: expected an integer in [1, 65536], got '12px'"},
        {"--width ''", "--width: expected an integer in [1, 65536], got ''"},
        {"--width 1e3", "--width: expected an integer"},
        {"--height 2147483648", "--height: expected an integer"},
        {"--width=64", "unknown option '--width=64'"},
        {"--range", "--range: missing value"},
        {"--aa fast",
         "--aa: expected one of \"stratified\", \"adaptive\", \"corners\", got 'fast'"},
        {"--view-dir 0,0,0",
         "--view-dir: expected a direction X,Y,Z of finite numbers, not all zero, got '0,0,0'"},
        {"--view-dir 1,2",
         "--view-dir: expected a direction X,Y,Z of finite numbers, not all zero, "
         "got '1,2'"},
        {"--shadow-terminator hanika",
         "--shadow-terminator: expected one of \"offset\", \"none\", got 'hanika'"},
        {"--aa-threshold -0.1", "--aa-threshold: expected a number >= 0, got '-0.1'"},
        {"--aa-depth 9", "--aa-depth: expected an integer in [0, 8], got '9'"},
        {"--aa-depth -1", "--aa-depth: expected an integer in [0, 8], got '-1'"},
        {"--view", "--view: missing value"},
        {"--exr-compression", "--exr-compression: missing value"},
        {"--exr-compression zstd",
         "--exr-compression: expected one of \"none\", \"rle\", \"zips\", \"zip\", \"piz\", "
         "\"pxr24\", \"b44\", \"b44a\", \"dwaa\", \"dwab\", got 'zstd'"},
        {"--exr-compression ZIP", "--exr-compression: expected one of"},
    };
    for (const Flag& f : flags) {
        expect_refused(std::string("render scene.nff -o out.png ") + f.args, "", f.expected, f.args,
                       2);
    }
    expect_refused("info", "info", "expected exactly one scene file", "info without scene", 2);
    expect_refused("info scene.nff scene.nff", "info", "expected exactly one scene file",
                   "info with two scenes", 2);
    // Values that parse but that the scene or the output cannot take: exit status 1.
    expect_refused("render scene.nff -o out.png --no-stream --width 30000 --height 30000",
                   "out.png", "too large for an in-memory film",
                   "an in-memory film over the pixel limit");
    expect_refused("render scene.nff -o out.png --display Nope", "out.png",
                   "unknown OCIO display 'Nope'", "unknown display");
    expect_refused("info nowhere.json", "nowhere.json", "cannot open", "info of a missing file");
}

// `rayo preview` refuses what `rayo render` refuses, with the same messages, and writes nothing.
TEST_F(BadInputCli, PreviewRefusesWhatRenderRefuses) {
    write("scene.nff", kGoodNff);
    fs::create_directories(m_dir / "folder.png");
    struct Case {
        std::string args, place, expected;
        int exit_code;
    };
    const Case cases[] = {
        {"preview nowhere.nff -o out.png", "nowhere.nff", "cannot open", 1},
        {"preview scene.nff -o out.bmpx", "out.bmpx", "unsupported image extension '.bmpx'", 1},
        {"preview scene.nff -o no/such/dir/x.png", "no/such/dir/x.png",
         "the directory 'no/such/dir' does not exist", 1},
        {"preview scene.nff -o folder.png", "folder.png", "cannot write: it is a directory", 1},
        {"preview scene.nff -o out.png --view Nope", "out.png", "unknown OCIO view 'Nope'", 1},
        {"preview scene.nff -o out.png --width 30000 --height 30000", "scene.nff#/camera",
         "too large for an in-memory image", 1},
        {"preview scene.nff -o out.png --width 12px", "",
         "--width: expected an integer in [1, 65536], got '12px'", 2},
        {"preview scene.nff -o out.png --threads 0", "", "--threads: expected an integer", 2},
        {"preview scene.nff -o out.png --spp 4", "", "unknown option '--spp'", 2},
        {"preview scene.nff -o", "", "-o: missing value", 2},
        {"preview scene.nff scene.nff -o out.png", "",
         "unexpected argument 'scene.nff': only one scene per preview", 2},
    };
    for (const Case& c : cases) expect_refused(c.args, c.place, c.expected, c.args, c.exit_code);
    // A scene with an error is refused with its place, as by render.
    write("bad.nff", std::string(kGoodNff) + "s 0 0 1\n");
    expect_refused("preview bad.nff -o out.png", "bad.nff:11", "'s' expects 4 numbers",
                   "bad scene");
}

}  // namespace
