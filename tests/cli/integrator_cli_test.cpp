// The registered integrators and the declared settings on the command line: --integrator and
// the flags generated from each integrator's fields, a flag given to the wrong integrator, and
// one declaration behind a flag and its JSON field (the same bound, the same message).
#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

#include "apps/cli/flag_table.h"
#include "apps/scene/scene_description.h"
#include "tests/cli/cli_fixture.h"

namespace {

using rayo_test::CommandResult;

class IntegratorCli : public rayo_test::CliFixture {};

const char* const kNff =
    "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 32 24\n"
    "b 0.1 0.2 0.3\nl 3 3 3\nf 1 0 0 0.8 0.2 20 0 1\ns 0 0 0 1\np 4\n-3 -1 -3\n3 -1 -3\n"
    "3 -1 3\n-3 -1 3\n";

TEST_F(IntegratorCli, AmbientOcclusionRendersWithItsOwnFlags) {
    write("scene.nff", kNff);
    const CommandResult r =
        run("render scene.nff --integrator ambient_occlusion --ao-samples 8 --ao-distance 2 "
            "-o ao.exr --quiet --stats");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("ambient_occlusion (samples 8, distance 2, direct off)"),
              std::string::npos)
        << r.output;
    const std::vector<float> ao = read_pixels("ao.exr");
    ASSERT_FALSE(ao.empty());
    // The image differs from Whitted's, and the sphere's AO (kd 0.8 × the unoccluded share)
    // never exceeds its diffuse colour.
    ASSERT_EQ(run("render scene.nff -o whitted.exr --quiet").exit_code, 0);
    EXPECT_NE(ao, read_pixels("whitted.exr"));
    for (size_t i = 0; i < ao.size(); i += 4) EXPECT_LE(ao[i], 1.0f);
}

TEST_F(IntegratorCli, AFlagOfAnotherIntegratorIsRefusedBeforeAnyWork) {
    write("scene.nff", kNff);
    const struct {
        const char* args;
        const char* message;
    } cases[] = {
        {"--ao-samples 4",
         "--ao-samples: a setting of the \"ambient_occlusion\" integrator, but "
         "this render's integrator is \"whitted\" (--integrator chooses)"},
        {"--integrator ambient_occlusion --max-depth 3",
         "--max-depth: a setting of the \"whitted\" and \"path\" integrators, but this "
         "render's integrator is \"ambient_occlusion\""},
        {"--light-strategy bsdf",
         "--light-strategy: a setting of the \"path\" integrator, but this render's integrator "
         "is \"whitted\""},
        {"--max-depth 100", "--max-depth: expected an integer in [0, 64], got '100'"},
        {"--integrator path --max-depth 0",
         "--max-depth: expected an integer in [1, 1024], got '0'"},
        {"--integrator paths",
         "--integrator: expected one of \"whitted\", \"ambient_occlusion\", \"path\", "
         "got 'paths'"},
        {"--integrator path --light-strategy both",
         "--light-strategy: expected one of \"mis\", \"light\", \"bsdf\", got 'both'"},
        {"--integrator ambient_occlusion --ao-samples 0",
         "--ao-samples: expected an integer in [1, 4096], got '0'"},
        {"--shadows soft", "--shadows: expected one of \"opaque\", \"filtered\", got 'soft'"},
        {"--min-contribution -1", "--min-contribution: expected a number >= 0, got '-1'"},
    };
    for (const auto& c : cases) {
        const CommandResult r = run(std::string("render scene.nff -o out.png ") + c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << " -> " << r.output;
        EXPECT_EQ(listing().count("out.png"), 0u) << c.args;
    }
}

TEST_F(IntegratorCli, AnEnvironmentThatCannotBeReadIsRefusedBeforeAnyOutput) {
    write("scene.nff", kNff);
    for (const char* image : {"missing.exr", "scene.nff"}) {
        const CommandResult r = run(
            std::string("render scene.nff -o out.png --integrator path --environment ") + image);
        EXPECT_EQ(r.exit_code, 1) << image;
        EXPECT_NE(r.output.find(std::string("--environment: ")), std::string::npos)
            << image << " -> " << r.output;
        EXPECT_NE(r.output.find(image), std::string::npos) << r.output;
        EXPECT_EQ(listing().count("out.png"), 0u) << image;
    }
}

TEST_F(IntegratorCli, AModelUnderAnEnvironmentGetsNoAutomaticLights) {
    // A 4x2 grey sky, as an EXR the test writes.
    {
        auto out = OIIO::ImageOutput::create((m_dir / "sky.exr").string());
        ASSERT_TRUE(out);
        ASSERT_TRUE(out->open((m_dir / "sky.exr").string(),
                              OIIO::ImageSpec(4, 2, 3, OIIO::TypeDesc::FLOAT)));
        const std::vector<float> grey(4 * 2 * 3, 0.5f);
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, grey.data()));
        out->close();
    }
    write("tri.obj", "v -1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const CommandResult lit = run("render tri.obj -o lit.png --width 32 --stats");
    ASSERT_EQ(lit.exit_code, 0) << lit.output;
    EXPECT_NE(lit.output.find("'key' directional"), std::string::npos) << lit.output;
    const CommandResult sky =
        run("render tri.obj -o sky.png --width 32 --stats --integrator path --environment sky.exr");
    ASSERT_EQ(sky.exit_code, 0) << sky.output;
    EXPECT_EQ(sky.output.find("'key'"), std::string::npos) << sky.output;
    EXPECT_NE(sky.output.find("'environment' environment image 4x2"), std::string::npos)
        << sky.output;
    EXPECT_NE(sky.output.find("32x24 1spp path"), std::string::npos) << sky.output;
    EXPECT_EQ(listing().count("sky.png"), 1u);
}

// The path wavefront times its stream calls: --stats gives each ray kind's rate (Whitted's
// coherent path does not time them, and says nothing).
TEST_F(IntegratorCli, PathStatsGiveATraceRatePerRayKind) {
    write("scene.nff", kNff);
    const CommandResult path =
        run("render scene.nff --integrator path --spp 4 -o path.exr --quiet --stats");
    ASSERT_EQ(path.exit_code, 0) << path.output;
    for (const char* kind : {"camera", "bounce", "shadow"}) {
        const std::string line = std::string("trace rate ") + kind;
        const size_t at = path.output.find(line);
        ASSERT_NE(at, std::string::npos) << line << "\n" << path.output;
        const double rate = std::stod(path.output.substr(at + 30));
        EXPECT_GT(rate, 0.0) << line;
    }
    const CommandResult whitted = run("render scene.nff -o whitted.exr --quiet --stats");
    ASSERT_EQ(whitted.exit_code, 0) << whitted.output;
    EXPECT_EQ(whitted.output.find("trace rate"), std::string::npos) << whitted.output;
}

TEST_F(IntegratorCli, AFlagTwoIntegratorsShareTakesEachOnesBounds) {
    write("scene.nff", kNff);
    EXPECT_EQ(run("render scene.nff -o w.png --quiet --max-depth 0").exit_code, 0);
    EXPECT_EQ(run("render scene.nff -o p.png --quiet --integrator path --max-depth 100").exit_code,
              0);
}

TEST_F(IntegratorCli, InfoListsEveryLightOfAJsonScene) {
    write("lit.json", R"({"rayo": 1, "environment": {"color": [0.2, 0.3, 0.4], "rotation": 15},
      "lights": [{"type": "point", "position": [0, 2, 0]},
                 {"type": "area", "shape": "disk", "center": [0, 3, 0], "normal": [0, -1, 0],
                  "radius": 0.5}]})");
    const CommandResult r = run("info lit.json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("light 0 point position 0 2 0 color 1 1 1 intensity 1\n"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("light 1 area disk color 1 1 1 intensity 1 area 0.785398 samples 16\n"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("light 2 environment color 0.2 0.3 0.4 intensity 1 rotation 15 "
                            "samples 16\n"),
              std::string::npos)
        << r.output;
}

TEST_F(IntegratorCli, AFlagAndItsJsonFieldShareOneBound) {
    // --spp and "render": {"spp"} are one declaration (RenderSettings::fields): the same limit,
    // the same words, whatever kMaxSpp is.
    const std::string limit = std::to_string(rayo::kMaxSpp);
    const std::string over = std::to_string(rayo::kMaxSpp + 1);
    const std::string expected = "expected an integer in [1, " + limit + "], got ";
    const CommandResult flag = run("render --spp " + over + " -o out.png");
    EXPECT_EQ(flag.exit_code, 2);
    EXPECT_NE(flag.output.find("--spp: " + expected + "'" + over + "'"), std::string::npos)
        << flag.output;
    write("over.json", "{\"rayo\": 1, \"render\": {\"spp\": " + over + "}}");
    const CommandResult json = run("render over.json -o out.png");
    EXPECT_EQ(json.exit_code, 1);
    EXPECT_NE(json.output.find("over.json#/render/spp: " + expected + over), std::string::npos)
        << json.output;
    // The limit itself is accepted by both (a 1×1 image keeps it quick).
    write("limit.json",
          "{\"rayo\": 1, \"camera\": {\"width\": 1, \"height\": 1}, \"render\": "
          "{\"spp\": " +
              limit + "}}");
    EXPECT_EQ(run("render limit.json -o a.exr --quiet").exit_code, 0);
    EXPECT_EQ(run("render limit.json --spp " + limit + " -o b.exr --quiet").exit_code, 0);
    EXPECT_EQ(listing().count("out.png"), 0u);

    // An integrator's flag and its field: --max-depth and "max_depth" of the "whitted"
    // integrator, the bound read from WhittedSettings::fields.
    rayo::RuleFinder depth{"max_depth"};
    rayo::WhittedSettings whitted;
    whitted.fields(depth);
    ASSERT_TRUE(depth.rule);
    const long long max_depth = static_cast<long long>(depth.rule->max);
    const std::string depth_expected = "expected an integer in [" +
                                       std::to_string(static_cast<long long>(depth.rule->min)) +
                                       ", " + std::to_string(max_depth) + "], got ";
    const std::string deep = std::to_string(max_depth + 1);
    const CommandResult depth_flag = run("render --max-depth " + deep + " -o out.png");
    EXPECT_EQ(depth_flag.exit_code, 2);
    EXPECT_NE(depth_flag.output.find("--max-depth: " + depth_expected + "'" + deep + "'"),
              std::string::npos)
        << depth_flag.output;
    write("deep.json",
          "{\"rayo\": 1, \"render\": {\"integrator\": {\"type\": \"whitted\", "
          "\"max_depth\": " +
              deep + "}}}");
    const CommandResult depth_json = run("render deep.json -o out.png");
    EXPECT_EQ(depth_json.exit_code, 1);
    EXPECT_NE(
        depth_json.output.find("deep.json#/render/integrator/max_depth: " + depth_expected + deep),
        std::string::npos)
        << depth_json.output;

    // The image size: --width and "camera": {"width"}, the bound read from
    // CameraDesc::resolution_fields (kMaxImageSide).
    rayo::RuleFinder width{"width"};
    rayo::CameraDesc camera;
    camera.resolution_fields(width);
    ASSERT_TRUE(width.rule);
    const long long max_width = static_cast<long long>(width.rule->max);
    EXPECT_EQ(max_width, rayo::kMaxImageSide);
    const std::string width_expected =
        "expected an integer in [1, " + std::to_string(max_width) + "], got ";
    const std::string wide = std::to_string(max_width + 1);
    const CommandResult width_flag = run("render --width " + wide + " -o out.png");
    EXPECT_EQ(width_flag.exit_code, 2);
    EXPECT_NE(width_flag.output.find("--width: " + width_expected + "'" + wide + "'"),
              std::string::npos)
        << width_flag.output;
    write("wide.json", "{\"rayo\": 1, \"camera\": {\"width\": " + wide + "}}");
    const CommandResult width_json = run("render wide.json -o out.png");
    EXPECT_EQ(width_json.exit_code, 1);
    EXPECT_NE(width_json.output.find("wide.json#/camera/width: " + width_expected + wide),
              std::string::npos)
        << width_json.output;
    // Both limits are accepted by flag and field (one row of pixels keeps it quick).
    write("edge.json",
          "{\"rayo\": 1, \"camera\": {\"width\": " + std::to_string(max_width) +
              ", \"height\": 1}, \"render\": {\"max_depth\": " + std::to_string(max_depth) + "}}");
    EXPECT_EQ(run("render edge.json -o c.exr --quiet").exit_code, 0);
    EXPECT_EQ(run("render edge.json --width " + std::to_string(max_width) + " --max-depth " +
                  std::to_string(max_depth) + " -o d.exr --quiet")
                  .exit_code,
              0);
    EXPECT_EQ(listing().count("out.png"), 0u);
}

TEST_F(IntegratorCli, HelpListsEveryIntegratorWithItsFlags) {
    const CommandResult r = run("render --help");
    ASSERT_EQ(r.exit_code, 0);
    for (const char* text :
         {"--integrator NAME", "whitted (default)", "--max-depth N", "--min-contribution X",
          "--shadows opaque|filtered", "ambient_occlusion", "--ao-samples N", "--ao-direct",
          "--spp N", "samples per pixel", "1..65536", "--aa stratified|adaptive",
          "--texture-cache X"}) {
        EXPECT_NE(r.output.find(text), std::string::npos) << text;
    }
    EXPECT_EQ(r.output.find('@'), std::string::npos) << "an unfilled help slot";
}

}  // namespace
