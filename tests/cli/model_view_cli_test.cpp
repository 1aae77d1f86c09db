// The camera a model file is rendered from, as `rayo info` and `rayo render --stats` print it
// (`view eye X Y Z, look_at X Y Z, up X Y Z`): the automatic framing of docs/scene-format.md
// ("Model files"), so that another renderer can be given the same view
// (scripts/model_gallery.sh).
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "tests/cli/cli_fixture.h"

namespace {

using rayo_test::CommandResult;

class ModelViewCli : public rayo_test::CliFixture {};

// An axis-aligned box from (1, 2, 3) to (3, 3, 7), away from the origin and longest along z.
const char* const kBoxObj =
    "v 1 2 3\nv 3 2 3\nv 3 3 3\nv 1 3 3\nv 1 2 7\nv 3 2 7\nv 3 3 7\nv 1 3 7\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

struct View {
    double eye[3], look_at[3], up[3];
};

double length(const double v[3]) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// The text after `prefix` on the line that starts with it (empty when there is none).
std::string line_after(const std::string& text, const std::string& prefix) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        if (line.compare(0, prefix.size(), prefix) == 0) return line.substr(prefix.size());
    }
    return "";
}

bool parse_view(const std::string& text, View& v) {
    return std::sscanf(text.c_str(), "eye %lf %lf %lf, look_at %lf %lf %lf, up %lf %lf %lf",
                       &v.eye[0], &v.eye[1], &v.eye[2], &v.look_at[0], &v.look_at[1], &v.look_at[2],
                       &v.up[0], &v.up[1], &v.up[2]) == 9;
}

// The documented framing: looking at the box's centre from `to_eye`, at the distance where the
// bounding sphere (half the diagonal) fills the vertical field of view with a 10 % margin.
void expect_framing(const View& v, const double to_eye[3], double vfov_degrees) {
    const double centre[3] = {2.0, 2.5, 5.0};
    const double radius = 0.5 * std::sqrt(2.0 * 2.0 + 1.0 * 1.0 + 4.0 * 4.0);
    double offset[3];
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(v.look_at[i], centre[i], 1e-4) << i;
        offset[i] = v.eye[i] - v.look_at[i];
    }
    const double distance = length(offset), norm = length(to_eye);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(offset[i] / distance, to_eye[i] / norm, 1e-4) << i;
    const double half_fov = 0.5 * vfov_degrees * M_PI / 180.0;
    EXPECT_NEAR(distance * std::sin(half_fov), 1.1 * radius, 1e-3 * radius);
}

TEST_F(ModelViewCli, InfoPrintsTheAutomaticFraming) {
    write("box.obj", kBoxObj);
    const CommandResult info = run("info box.obj");
    ASSERT_EQ(info.exit_code, 0) << info.output;
    View v{};
    ASSERT_TRUE(parse_view(line_after(info.output, "view "), v)) << info.output;
    double hfov = 0.0, vfov = 0.0;
    ASSERT_EQ(std::sscanf(line_after(info.output, "fov ").c_str(), "%lfx%lf", &hfov, &vfov), 2)
        << info.output;
    EXPECT_NEAR(vfov, 40.0, 1e-4);
    const double default_direction[3] = {0.6, 0.45, 1.0};
    expect_framing(v, default_direction, vfov);
    EXPECT_EQ(v.up[0], 0.0);
    EXPECT_EQ(v.up[1], 1.0);
    EXPECT_EQ(v.up[2], 0.0);
}

// --stats prints the camera the render used: the same as `rayo info`'s by default, and the one
// --view-dir asks for; the field of view follows the output's shape (vertical 40° kept).
TEST_F(ModelViewCli, StatsPrintTheRenderedView) {
    write("box.obj", kBoxObj);
    const CommandResult info = run("info box.obj");
    ASSERT_EQ(info.exit_code, 0) << info.output;
    const CommandResult square = run("render box.obj --width 16 --height 16 --stats -o a.png");
    ASSERT_EQ(square.exit_code, 0) << square.output;
    const std::string stats_view = line_after(square.output, "  view");
    const std::string info_view = line_after(info.output, "view ");
    ASSERT_FALSE(info_view.empty()) << info.output;
    EXPECT_NE(stats_view.find(info_view + ", fov 40x40 degrees"), std::string::npos)
        << stats_view << "\n"
        << info.output;
    // The lights the render used, as `rayo info` lists them: the key and fill of this view.
    const std::string key = line_after(info.output, "light 0 ");
    ASSERT_NE(key.find("'key' directional direction "), std::string::npos) << info.output;
    const std::string key_light = key.substr(key.find("'key'"));
    EXPECT_NE(square.output.find(key_light), std::string::npos) << square.output;

    const CommandResult back =
        run("render box.obj --view-dir 0,0,-1 --width 16 --height 8 --stats -o b.png");
    ASSERT_EQ(back.exit_code, 0) << back.output;
    const std::string text = line_after(back.output, "  view");
    const size_t start = text.find("eye ");
    ASSERT_NE(start, std::string::npos) << back.output;
    View v{};
    ASSERT_TRUE(parse_view(text.substr(start), v)) << back.output;
    const double from_behind[3] = {0.0, 0.0, -1.0};
    expect_framing(v, from_behind, 40.0);
    EXPECT_NE(text.find("x40 degrees"), std::string::npos) << text;
    EXPECT_EQ(text.find("fov 40x40"), std::string::npos) << "a 2:1 image is wider: " << text;
    // The key light turns with the view: not the default view's.
    EXPECT_NE(back.output.find("'key' directional direction "), std::string::npos) << back.output;
    EXPECT_EQ(back.output.find(key_light), std::string::npos) << back.output;
}

}  // namespace
