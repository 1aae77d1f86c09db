// `rayo bench suite`: the SPD suite run through the executable at a tiny size (the smoke test CI
// runs; no timing is checked), its files, --write-nff and its bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "apps/cli/int_flag.h"
#include "tests/cli/cli_fixture.h"

namespace {

namespace fs = std::filesystem;
using rayo_test::CommandResult;

class BenchSuiteTest : public rayo_test::CliFixture {
  protected:
    std::string read_text(const std::string& name) const {
        std::ifstream in(m_dir / name);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
};

const char* const kScenes[] = {"balls", "gears", "mount", "rings", "teapot", "tetra", "tree"};

TEST_F(BenchSuiteTest, WritesTheTableAndFilesForEveryScene) {
    const CommandResult r = run("bench suite --size 1 --width 32 --threads 1 -o out");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("Mrays/s"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("machine: "), std::string::npos) << r.output;
    for (const char* file : {"suite.csv", "suite.json", "suite.md", "suite.gp", "suite.png"}) {
        EXPECT_TRUE(fs::exists(m_dir / "out" / file)) << file;
    }
    const std::string csv = read_text("out/suite.csv");
    EXPECT_EQ(csv.rfind("scene,size,width,primitives,rays_camera,", 0), 0u) << csv;
    for (const char* scene : kScenes) {
        // One row each: size 1, 32 pixels, 32² camera rays, one thread.
        EXPECT_NE(csv.find(std::string("\n") + scene + ",1,32,"), std::string::npos) << scene;
        EXPECT_NE(read_text("out/suite.json").find(std::string("\"scene\": \"") + scene + "\""),
                  std::string::npos)
            << scene;
        EXPECT_NE(read_text("out/suite.md").find(std::string("| ") + scene + " "),
                  std::string::npos)
            << scene;
    }
    EXPECT_NE(csv.find(",1024,"), std::string::npos) << csv;  // 32² camera rays
    EXPECT_GT(fs::file_size(m_dir / "out" / "suite.png"), 1000u);
}

// The SPD's testing procedure at 128² (CI's smoke test): every database at its default size,
// 129² corner rays each, the counts beside the Readme's, exit 0 when all are within 10%.
TEST_F(BenchSuiteTest, TheSpdProcedureChecksTheCountsAgainstTheReadme) {
    const CommandResult r = run("bench suite --procedure spd --width 128 --threads 2 -o out");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("Ray counts against the SPD Readme's \"Database Analysis\""),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("input s  setup s  ray tracing s"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("every ray count within 10% of the SPD Readme's"), std::string::npos)
        << r.output;
    const std::string csv = read_text("out/suite.csv");
    const std::pair<const char*, int> defaults[] = {{"balls", 4}, {"gears", 4},   {"mount", 6},
                                                    {"rings", 7}, {"teapot", 12}, {"tetra", 6},
                                                    {"tree", 11}};
    for (const auto& [scene, size] : defaults) {
        // SCENE,SIZE,128,primitives,129² camera rays
        const size_t at =
            csv.find(std::string("\n") + scene + "," + std::to_string(size) + ",128,");
        ASSERT_NE(at, std::string::npos) << scene << "\n" << csv;
        const std::string line = csv.substr(at + 1, csv.find('\n', at + 1) - at - 1);
        EXPECT_NE(line.find(",16641,"), std::string::npos) << line;
    }
    const std::string md = read_text("out/suite.md");
    EXPECT_NE(md.find("`rayo bench suite --procedure spd --width 128 --threads 2 -o out`"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| eye hit rayo |"), std::string::npos) << md;
}

TEST_F(BenchSuiteTest, TheSpdProcedureFailsLoudlyWhenACountIsOff) {
    // At 32² pixels (33² corners) mount's glass spheres take 15% fewer rays than the Readme's
    // 513² corners, scaled: beyond the Readme's 10%.
    const CommandResult r = run("bench suite --procedure spd --width 32 --scenes mount");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("rayo bench suite --procedure spd: FAILED: mount refract rays: "),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("more than 10% off"), std::string::npos) << r.output;
}

TEST_F(BenchSuiteTest, RepetitionsGiveTheMedianMinAndMax) {
    const CommandResult r =
        run("bench suite --size 1 --width 16 --threads 1 --scenes tetra --repetitions 3");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("times: median (min-max) of 3 repetitions"), std::string::npos)
        << r.output;
}

TEST_F(BenchSuiteTest, WritesTheGeneratedNffFiles) {
    const CommandResult r = run("bench suite --size 2 --scenes tetra,tree --write-nff -o nff");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string tetra = read_text("nff/tetra_2.nff");
    size_t triangles = 0;
    for (size_t at = tetra.find("\np 3\n"); at != std::string::npos;
         at = tetra.find("\np 3\n", at + 1)) {
        ++triangles;
    }
    EXPECT_EQ(triangles, 16u);  // 4^2
    EXPECT_TRUE(fs::exists(m_dir / "nff" / "tree_2.nff"));
    EXPECT_FALSE(fs::exists(m_dir / "nff" / "balls_2.nff"));
    // The written file renders like any NFF file.
    const CommandResult render = run("render nff/tree_2.nff --width 16 --quiet -o tree.png");
    EXPECT_EQ(render.exit_code, 0) << render.output;
}

TEST_F(BenchSuiteTest, BadOptionsAreClearErrors) {
    // --scenes is checked against the suite's scene list (the one its help names) before any
    // work: a usage error.
    CommandResult r = run("bench suite --scenes balls,bunny --size 1 --width 8");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--scenes: expected a comma-separated list of balls,gears,"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("got 'balls,bunny' ('bunny')"), std::string::npos) << r.output;
    r = run("bench suite --size 7 --scenes balls --width 8");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("up to size 6"), std::string::npos) << r.output;
    r = run("bench suite --write-nff");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    r = run("bench suite --procedure spd --size 3");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("renders each database at its default size"), std::string::npos)
        << r.output;
    r = run("bench suite --procedure povray");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--procedure: expected one of \"spd\", got 'povray'"),
              std::string::npos)
        << r.output;
    r = run("bench suite --frobnicate");
    EXPECT_EQ(r.exit_code, 2) << r.output;
}

// The bench commands' flags are declared once (kAccuracyFlags, kSuiteFlags in apps/cli/cli.cpp,
// their bounds in apps/cli/int_flag.h, which the Python module shares): --help states each bound
// and choice, and the parser refuses a value beyond it with the same numbers.
TEST_F(BenchSuiteTest, HelpStatesTheBoundsTheParserEnforces) {
    const auto range = [](rayo::IntRange r) {
        return std::to_string(r.min) + ".." + std::to_string(r.max);
    };
    const auto expected = [](rayo::IntRange r, int got) {
        return "expected an integer in [" + std::to_string(r.min) + ", " + std::to_string(r.max) +
               "], got '" + std::to_string(got) + "'";
    };
    const CommandResult help = run("bench --help");
    ASSERT_EQ(help.exit_code, 0);
    for (const std::string& text :
         {"scenes of N×N pixels, " + range(rayo::kAccuracySizeRange),
          std::string("--only spheres|shapes"),
          "SPD size of every scene, " + range(rayo::kSuiteSizeRange),
          "images of W×W pixels, " + range(rayo::kSuiteWidthRange),
          "worker threads, " + range(rayo::kSuiteThreadsRange), std::string("--scenes A,B"),
          std::string("a comma-separated list of"),
          std::string("balls,gears,mount,rings,teapot,tetra,tree")}) {
        EXPECT_NE(help.output.find(text), std::string::npos) << text << "\n" << help.output;
    }
    const struct {
        std::string args, message;
    } refused[] = {
        {"bench accuracy -o out --size " + std::to_string(rayo::kAccuracySizeRange.min - 1),
         "--size: " + expected(rayo::kAccuracySizeRange, rayo::kAccuracySizeRange.min - 1)},
        {"bench accuracy -o out --only cones",
         "--only: expected one of \"spheres\", \"shapes\", got 'cones'"},
        {"bench suite --size " + std::to_string(rayo::kSuiteSizeRange.max + 1),
         "--size: " + expected(rayo::kSuiteSizeRange, rayo::kSuiteSizeRange.max + 1)},
        {"bench suite --width " + std::to_string(rayo::kSuiteWidthRange.min - 1),
         "--width: " + expected(rayo::kSuiteWidthRange, rayo::kSuiteWidthRange.min - 1)},
        {"bench suite --threads " + std::to_string(rayo::kSuiteThreadsRange.max + 1),
         "--threads: " + expected(rayo::kSuiteThreadsRange, rayo::kSuiteThreadsRange.max + 1)},
        {"bench suite --repetitions " + std::to_string(rayo::kSuiteRepetitionsRange.min - 1),
         "--repetitions: " +
             expected(rayo::kSuiteRepetitionsRange, rayo::kSuiteRepetitionsRange.min - 1)},
        {"bench accuracy -o out stray", "bench accuracy: unexpected argument 'stray'"},
    };
    for (const auto& r : refused) {
        const CommandResult c = run(r.args);
        EXPECT_EQ(c.exit_code, 2) << r.args << ": " << c.output;
        EXPECT_NE(c.output.find("rayo: error: " + r.message), std::string::npos)
            << r.args << ": " << c.output;
    }
    EXPECT_FALSE(fs::exists(m_dir / "out"));
}

}  // namespace
