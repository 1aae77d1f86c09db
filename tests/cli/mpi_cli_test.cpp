// `rayo render` under `mpirun` (apps/mpi, docs/distributed.md): the same bits as one process for
// any number of ranks and threads per rank, errors printed once, the ranks in the summary.
// Built only when rayo is built with MPI (setup.sh installs Open MPI); rayo runs as one
// process otherwise, which every other test covers.
#if RAYO_HAVE_MPI
#include <unistd.h>

#include "tests/cli/cli_fixture.h"

namespace rayo_test {
namespace {

// Mirrors, glass and shadows, so that every ray kind runs on every rank; 96×64 in tiles of 16
// is 24 tiles.
constexpr const char* kScene = R"(b 0.1 0.2 0.3
v
from 0 1 -6
at 0 0.5 0
up 0 1 0
angle 40
hither 0.01
resolution 96 64
l 4 6 -4
l -5 3 -2
f 0.8 0.3 0.2 0.7 0.3 20 0 1
s -1 0.6 0 0.6
f 0.9 0.9 0.9 0.1 0.3 40 0.8 1.5
s 0.7 0.6 -0.5 0.6
f 0.3 0.8 0.3 0.8 0.5 10 0.5 1
s 0.4 0.3 1.5 0.3
f 0.6 0.6 0.6 0.9 0 1 0 1
p 4
-8 0 -8
-8 0 8
8 0 8
8 0 -8
)";

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RAYO_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define RAYO_TEST_ASAN 1
#endif

class MpiCli : public CliFixture {
  protected:
    static std::string mpirun(int ranks) {
        std::string launcher;
#ifdef RAYO_TEST_ASAN
        // Open MPI's MPI_Init leaks by design, in components it unloads again at MPI_Finalize
        // (the reports have no symbols to suppress by), so the ranks run without the leak check;
        // every other test checks rayo's own allocations for leaks.
        launcher = "ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" ";
#endif
        launcher += "'" RAYO_MPIRUN_PATH "' --oversubscribe -np " + std::to_string(ranks);
        if (::geteuid() == 0) launcher += " --allow-run-as-root";
        return launcher;
    }
};

TEST_F(MpiCli, SameBitsAsOneProcessForAnyRanksAndThreads) {
    write("scene.nff", kScene);
    ASSERT_EQ(run("render scene.nff --tile-size 16 --quiet -o one.exr").exit_code, 0);
    const std::vector<float> one = read_pixels("one.exr");
    ASSERT_EQ(one.size(), 96u * 64u * 4u);
    const struct {
        int ranks;
        const char* args;
    } cases[] = {{2, "--threads 1"}, {3, "--threads 1"}, {3, "--threads 2"}, {4, "--threads 1"}};
    for (const auto& c : cases) {
        const CommandResult r =
            run(std::string("render scene.nff --tile-size 16 --quiet -o many.exr ") + c.args,
                mpirun(c.ranks));
        ASSERT_EQ(r.exit_code, 0) << c.ranks << " ranks: " << r.output;
        EXPECT_EQ(read_pixels("many.exr"), one) << c.ranks << " ranks " << c.args;
    }
}

TEST_F(MpiCli, AdaptiveAntialiasingAndLargeTilesToo) {
    write("scene.nff", kScene);
    const std::string args = "render scene.nff --aa adaptive --tile-size 32 --quiet -o ";
    ASSERT_EQ(run(args + "one.exr").exit_code, 0);
    const CommandResult r = run(args + "many.exr --threads 1", mpirun(3));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(read_pixels("many.exr"), read_pixels("one.exr"));
    EXPECT_EQ(read_pixels("one.exr").size(), 96u * 64u * 4u);
}

TEST_F(MpiCli, SummaryAndStatsNameTheRanks) {
    write("scene.nff", kScene);
    const CommandResult r =
        run("render scene.nff --tile-size 16 --threads 1 --stats -o x.exr", mpirun(3));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("1 threads x 3 ranks"), std::string::npos) << r.output;
    // One line per rank; their tiles add up to the 24 of the grid.
    int tiles = 0;
    for (int rank = 0; rank < 3; ++rank) {
        const std::string label = "rank " + std::to_string(rank);
        const size_t at = r.output.find(label);
        ASSERT_NE(at, std::string::npos) << r.output;
        tiles += std::stoi(r.output.substr(r.output.find_first_not_of(' ', at + label.size())));
    }
    EXPECT_EQ(tiles, 24);
    // One summary line, from rank 0 only.
    EXPECT_EQ(r.output.find("rayo: x.exr"), r.output.rfind("rayo: x.exr")) << r.output;
}

TEST_F(MpiCli, AnErrorOnEveryRankIsPrintedOnceAndLeavesNoFile) {
    write("bad.nff", "v\nfrom 0 0 0\nat 0 0 0\n");
    const CommandResult bad = run("render bad.nff -o x.exr", mpirun(3));
    EXPECT_EQ(bad.exit_code, 1) << bad.output;
    const size_t first = bad.output.find("rayo: error:");
    ASSERT_NE(first, std::string::npos) << bad.output;
    EXPECT_EQ(first, bad.output.rfind("rayo: error:")) << bad.output;
    EXPECT_EQ(listing().count("x.exr"), 0u);

    const CommandResult usage = run("render --width 0 -o x.exr", mpirun(2));
    EXPECT_EQ(usage.exit_code, 2) << usage.output;
    EXPECT_EQ(usage.output.find("rayo: error:"), usage.output.rfind("rayo: error:"));
}

TEST_F(MpiCli, AnUnwritableOutputOnRankZeroStopsEveryRank) {
    write("scene.nff", kScene);
    const CommandResult r = run("render scene.nff -o missing/x.exr", mpirun(2));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("missing"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("rayo: error:"), r.output.rfind("rayo: error:"));
}

// Progressive passes (core/progressive.h) shared out among the ranks: rank 0 accumulates and
// decides for every rank when to stop, so the image, the passes and the noise are the same as
// in one process; the summary is printed once.
TEST_F(MpiCli, ProgressiveRendersGiveTheSameBitsAndPassesAsOneProcess) {
    write("scene.nff", kScene);
    const std::string args =
        "render scene.nff --tile-size 16 --pass-spp 2 --max-spp 16 --noise-target 0.02 -o ";
    const CommandResult one = run(args + "one.exr");
    ASSERT_EQ(one.exit_code, 0) << one.output;
    const size_t at = one.output.find(" passes, noise ");
    ASSERT_NE(at, std::string::npos) << one.output;
    const std::string passes = one.output.substr(one.output.rfind('(', at), 40);
    for (int ranks : {2, 3}) {
        const CommandResult many = run(args + "many.exr --threads 1", mpirun(ranks));
        ASSERT_EQ(many.exit_code, 0) << ranks << " ranks: " << many.output;
        EXPECT_EQ(read_pixels("many.exr"), read_pixels("one.exr")) << ranks << " ranks";
        EXPECT_NE(many.output.find(passes), std::string::npos) << passes << "\n" << many.output;
        EXPECT_EQ(many.output.find("rayo: many.exr"), many.output.rfind("rayo: many.exr"))
            << many.output;
    }
}

// No partial render under mpirun (docs/high-resolution.md, "Interrupt and resume"): none is
// left by a render, and --resume is refused once, by every rank.
TEST_F(MpiCli, ResumeIsRefusedAndNoPartialRenderIsKept) {
    write("scene.nff", kScene);
    const CommandResult r = run("render scene.nff --tile-size 16 -o x.exr", mpirun(2));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(listing(), (std::set<std::string>{"scene.nff", "x.exr"}));
    const CommandResult resume = run("render scene.nff -o y.exr --resume", mpirun(2));
    EXPECT_EQ(resume.exit_code, 2) << resume.output;
    EXPECT_NE(resume.output.find("rayo: error: --resume: not available under mpirun"),
              std::string::npos)
        << resume.output;
    EXPECT_EQ(resume.output.find("rayo: error:"), resume.output.rfind("rayo: error:"));
    EXPECT_EQ(listing(), (std::set<std::string>{"scene.nff", "x.exr"}));
}

}  // namespace
}  // namespace rayo_test
#endif
