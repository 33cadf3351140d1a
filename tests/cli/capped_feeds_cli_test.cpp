// A feed the machine's axes cannot give is run at their limit and said, naming the line, by every
// command that simulates the program.
#include <gtest/gtest.h>

#include <string>

#include "scratch_files.h"
#include "test_support.h"

using isurface::test::runCli;
using isurface::test::scratchDir;

namespace isurface {
namespace {

std::string program(const std::string& name, const std::string& text) {
  return test::writeScratch(name, text);
}

TEST(cappedFeedsCli, aFeedAboveTheAxesLimitIsNamedWithItsLine) {
  // A raster of six passes whose second move asks for 9,991,300 mm/min, as does the fourth.
  std::string text = "G21 G90 G17\nG0 X0 Y0 Z0\nG1 X10 F3000\nG1 Y0.5 F9991300\nG1 X0 F3000\nG1 Y1 F9991300\n";
  for (int pass = 2; pass < 6; ++pass)
    text += (pass % 2 ? "G1 X0\n" : "G1 X10 F2000\n") + std::string("G1 Y") + std::to_string(0.5 * (pass + 1)) + "\n";
  const std::string path = program("capped-feed.nc", text + "M2\n");
  const std::string dump = (scratchDir() / "capped-feed.biip").string();
  const test::CommandResult simulated = runCli("simulate " + path + " -o " + dump);
  EXPECT_EQ(simulated.exitCode, 0) << simulated.err;
  EXPECT_NE(simulated.err.find("warning: " + path + ":4:"), std::string::npos) << simulated.err;
  EXPECT_NE(simulated.err.find("F9991300 is faster than the machine's axes allow along this move (24000 mm/min)"),
            std::string::npos)
      << simulated.err;
  EXPECT_NE(simulated.err.find("as 1 more move does"), std::string::npos) << simulated.err;
  // The commands that simulate in memory say it too.
  const test::CommandResult analysed = runCli("analyze " + path + " -o " + (scratchDir() / "capped.json").string());
  EXPECT_NE(analysed.err.find("F9991300 is faster"), std::string::npos) << analysed.err;
}

TEST(cappedFeedsCli, feedsWithinTheLimitsAndRapidsSayNothing) {
  const std::string path = program("fast-rapid.nc", "G21 G90\nG0 X100 Y100 Z10\nG1 X0 F24000\nG1 Y0 F3000\nM2\n");
  const test::CommandResult simulated = runCli("simulate " + path + " -o " + (scratchDir() / "fast-rapid.biip").string());
  EXPECT_EQ(simulated.exitCode, 0) << simulated.err;
  EXPECT_EQ(simulated.err.find("faster than the machine's axes"), std::string::npos) << simulated.err;
}

}  // namespace
}  // namespace isurface
