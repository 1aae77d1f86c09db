// Tests of `rayo render --gi radiosity` and `--gi-view` (docs/radiosity.md): the summary line
// (patches, solve time, shots, form-factor rays), the flag errors, that the flat patch view
// differs from the smooth one, and the warning for general quadrics (not tessellated).
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "tests/cli/cli_fixture.h"

namespace rayo {
namespace {

using rayo_test::CommandResult;

class RadiosityCli : public rayo_test::CliFixture {};

// A small room: a floor, a back wall and an emissive ceiling patch.
const char* const kRoom = R"({"rayo": 1,
  "camera": {"eye": [0, 1, 3], "look_at": [0, 0.5, 0], "width": 24, "height": 16},
  "radiosity": {"patch_size": 0.5, "threshold": 0.01, "rays": 4},
  "materials": {"default": {"kd": 0.6, "ka": 0},
                "lamp": {"kd": 0, "ka": 0, "emission": 4}},
  "objects": [
    {"type": "polygon", "vertices": [[-1,0,-1], [-1,0,1], [1,0,1], [1,0,-1]]},
    {"type": "polygon", "vertices": [[-1,0,-1], [1,0,-1], [1,2,-1], [-1,2,-1]]},
    {"type": "polygon", "material": "lamp",
     "vertices": [[-0.3,1.5,-0.3], [0.3,1.5,-0.3], [0.3,1.5,0.3], [-0.3,1.5,0.3]]}]})";

TEST_F(RadiosityCli, RendersWithASummaryLine) {
    write("room.json", kRoom);
    const CommandResult r =
        run("render room.json --gi radiosity --gi-log unshot.csv --stats -o room.exr");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("radiosity shots"), std::string::npos) << r.output;
    // The log: a header and one line per shot, the unshot fraction falling to the threshold.
    std::ifstream log(m_dir / "unshot.csv");
    std::string line;
    ASSERT_TRUE(std::getline(log, line));
    EXPECT_EQ(line, "shot,unshot_fraction");
    int shots = 0;
    double last = 1.0;
    while (std::getline(log, line)) {
        ++shots;
        EXPECT_EQ(line.substr(0, line.find(',')), std::to_string(shots));
        last = std::stod(line.substr(line.find(',') + 1));
    }
    EXPECT_GT(shots, 1);
    EXPECT_LE(last, 0.01);
    EXPECT_NE(r.output.find(std::to_string(shots) + " shots"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("rayo: radiosity "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(" patches | solve "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(" shots, unshot "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("form-factor rays "), std::string::npos) << r.output;
    // Without --gi the scene's default ("none") runs no solve.
    const CommandResult none = run("render room.json -o none.exr");
    ASSERT_EQ(none.exit_code, 0) << none.output;
    EXPECT_EQ(none.output.find("rayo: radiosity"), std::string::npos) << none.output;
}

TEST_F(RadiosityCli, PatchViewDiffersFromTheSmoothOne) {
    write("room.json", kRoom);
    ASSERT_EQ(run("render room.json --gi radiosity --quiet -o smooth.exr").exit_code, 0);
    ASSERT_EQ(
        run("render room.json --gi radiosity --gi-view patches --quiet -o flat.exr").exit_code, 0);
    const CommandResult same = run("render room.json --gi radiosity --quiet -o again.exr");
    ASSERT_EQ(same.exit_code, 0);
    // The pixels (the files' metadata hold the render time).
    const std::vector<float> smooth = read_pixels("smooth.exr");
    ASSERT_EQ(smooth.size(), 24u * 16u * 4u);
    EXPECT_EQ(smooth, read_pixels("again.exr"));
    EXPECT_NE(smooth, read_pixels("flat.exr"));
}

TEST_F(RadiosityCli, WarnsThatGeneralQuadricsAreNotInTheSolve) {
    std::string room = kRoom;
    room.insert(room.rfind("]}"),
                R"(, {"type": "quadric", "coefficients": [1, 1, 1, 0, 0, 0, 0, 0, 0, -0.04],
                      "bounds": {"min": [-0.3, 0, -0.3], "max": [0.3, 0.5, 0.3]}})");
    write("room.json", room);
    const CommandResult r = run("render room.json --gi radiosity -o room.exr");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("warning: radiosity: 1 quadric(s) have no tessellation"),
              std::string::npos)
        << r.output;
    const CommandResult none = run("render room.json -o none.exr");
    ASSERT_EQ(none.exit_code, 0) << none.output;
    EXPECT_EQ(none.output.find("no tessellation"), std::string::npos) << none.output;
}

TEST_F(RadiosityCli, WarnsThatVoxelGridsAreNotInTheSolve) {
    std::string room = kRoom;
    room.insert(room.rfind("]}"), R"(, {"type": "voxels", "file": "v.raw", "dims": [2, 2, 2],
                                      "size": [0.4, 0.4, 0.4], "origin": [-0.2, 0, -0.2]})");
    write("room.json", room);
    write("v.raw", std::string(8, '\xff'));
    const CommandResult r = run("render room.json --gi radiosity -o room.exr");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("warning: radiosity: 1 voxel grid(s) are not in the solve"),
              std::string::npos)
        << r.output;
}

TEST_F(RadiosityCli, BadFlagsAreRefused) {
    const struct {
        const char* args;
        const char* message;
    } cases[] = {
        {"render --gi path -o x.png", "--gi: expected one of \"none\", \"radiosity\", got 'path'"},
        {"render --gi-view flat -o x.png",
         "--gi-view: expected one of \"smooth\", \"patches\", got 'flat'"},
        {"render --gi -o x.png", "got '-o'"},
    };
    for (const auto& c : cases) {
        const CommandResult r = run(c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << " -> " << r.output;
    }
}

}  // namespace
}  // namespace rayo
