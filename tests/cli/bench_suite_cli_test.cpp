// `rayo bench suite`: the SPD suite run through the executable at a tiny size (the smoke test CI
// runs; no timing is checked), its files, --write-nff and its bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

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
    CommandResult r = run("bench suite --scenes bunny --size 1 --width 8");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("spd:bunny"), std::string::npos) << r.output;
    r = run("bench suite --size 7 --scenes balls --width 8");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("up to size 6"), std::string::npos) << r.output;
    r = run("bench suite --write-nff");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    r = run("bench suite --frobnicate");
    EXPECT_EQ(r.exit_code, 2) << r.output;
}

}  // namespace
