#pragma once
// The bad-input catalogue's fixture (tests/cli/bad_input_files_test.cpp,
// bad_input_round_three_test.cpp): runs the `rayo` executable on a file the test wrote and
// checks the exit status, the message (place and reason), that nothing is left behind, and that
// time and memory stay bounded.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "tests/cli/cli_fixture.h"

namespace rayo_test {

// Generous bounds that the failures these tests guard against exceed by far: reading /dev/zero
// grew to 4.3 GB in 15 s, and a FIFO blocked forever.
constexpr double kSecondsLimit = 60.0;
constexpr long kPeakRssLimitKb = 600 * 1024;

// A camera and a light for JSON scenes of the catalogue: 32 × 24 pixels.
inline const char* const kCamera =
    R"("camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "hfov": 40, "width": 32,
       "height": 24}, "lights": [{"type": "point", "position": [5, 5, 5]}])";

class BadInputFixture : public CliFixture {
  protected:
    // Runs `args`, expects exit status 1 within the bounds, "rayo: error: PLACE: " and EXPECTED
    // in the message, and the folder as it was before.
    void expect_refused(const std::vector<std::string>& args, const std::string& place,
                        const std::string& expected, const std::string& label) {
        const std::set<std::string> before = listing();
        const WatchedResult r = run_watched(args, kSecondsLimit);
        EXPECT_FALSE(r.timed_out) << label << ": still running after " << kSecondsLimit << " s";
        EXPECT_EQ(r.exit_code, 1) << label << "\n" << r.output;
        EXPECT_NE(r.output.find("rayo: error: " + place + ": "), std::string::npos)
            << label << ": the message must name " << place << "\n"
            << r.output;
        EXPECT_NE(r.output.find(expected), std::string::npos)
            << label << ": expected '" << expected << "'\n"
            << r.output;
        EXPECT_LT(r.peak_rss_kb, kPeakRssLimitKb) << label << ": memory not bounded";
        EXPECT_EQ(listing(), before) << label << ": a file was left behind";
    }
};

}  // namespace rayo_test
