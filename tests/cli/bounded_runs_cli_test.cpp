// Runs bounded up front by what the program implies: a program of long dwells, binary data on a
// pipe or an out-of-range pick is refused at once with a clear message, never a disk filled or
// a bad_alloc.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scratch_files.h"
#include "test_support.h"

namespace fs = std::filesystem;
using isurface::test::runCli;
using isurface::test::scratchDir;
using isurface::test::writeScratch;

TEST(BoundedRuns, ARunLongerThanTheBoundIsRefusedBeforeItsSamplesAreMade) {
  // Five dwells of 22 hours: 110 hours, 396 million samples.
  std::string dwells = "G21 G90\n";
  for (int i = 0; i < 5; ++i) dwells += "G4 P80000\n";
  const std::string program = writeScratch("dwells.nc", dwells + "M2\n");
  const std::string dump = (scratchDir() / "dwells.biip").string();
  for (const std::string& command : {"simulate " + program + " -o " + dump, "render " + program + " -o " + dump + ".png"}) {
    const auto r = runCli(command);
    EXPECT_EQ(r.exitCode, 2) << command << "\n" << r.err;
    EXPECT_NE(r.err.find("the run passes 100 h of machining"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--max-hours"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(dump));
}

TEST(BoundedRuns, TheBoundIsTheUsersToSet) {
  const std::string program = writeScratch("ten-seconds.nc", "G21 G90\nG1 X10 F60\nM2\n");
  const std::string dump = (scratchDir() / "ten-seconds.biip").string();
  const auto refused = runCli("simulate " + program + " -o " + dump + " --max-hours 0.001");
  EXPECT_EQ(refused.exitCode, 2) << refused.err;
  EXPECT_NE(refused.err.find("ten-seconds.nc:2:"), std::string::npos) << refused.err;
  const auto accepted = runCli("simulate " + program + " -o " + dump + " --max-hours 0.01");
  EXPECT_EQ(accepted.exitCode, 0) << accepted.err;
}

// LinuxCNC's planner runs cycle by cycle: a move at a crawl (an acceleration of 1e-12 mm/s^2)
// is stopped at the bound as it is sampled, not after years of samples.
TEST(BoundedRuns, ACrawlOnLinuxCncsPlannerStopsAtTheBound) {
  const std::string program = writeScratch("crawl.nc", "G21 G90 F1000\nG1 X1\nM30\n");
  const std::string machine = writeScratch(
      "crawl-machine.json",
      R"({"control": {"planner": "linuxcnc-2.9"}, "axes": {"x": {"max_acceleration_mm_s2": 1e-12},
          "y": {"max_acceleration_mm_s2": 1e-12}, "z": {"max_acceleration_mm_s2": 1e-12}}})");
  const std::string dump = (scratchDir() / "crawl.biip").string();
  const auto r = runCli("simulate " + program + " --machine " + machine + " -o " + dump + " --max-hours 0.2");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("crawl.nc:2:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the run passes 0.2 h of machining"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dump));
}

// A pipe that never ends with text (every line the same zero-length move, which takes no time)
// is refused once it passes 2 GB, within seconds, and nothing is written.
TEST(BoundedRuns, ATextPipeThatNeverEndsIsRefused) {
  const std::string dump = (scratchDir() / "endless-pipe.biip").string();
  const auto r = isurface::test::runShell("yes 'G1 X1 F100' | timeout 120 " + std::string(isurface::test::cliProgram()) +
                                         " simulate /dev/stdin -o " + dump);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("more than 2 GB through a pipe"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dump));
}

TEST(BoundedRuns, BinaryDataOnAPipeIsRefusedAtOnce) {
  const auto r = runCli("canon /dev/zero");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("NUL byte at byte 1"), std::string::npos) << r.err;
}

TEST(BoundedRuns, AProgramThroughAPipeReadsAsFromItsFile) {
  const std::string program = writeScratch("piped.nc", "G21 G90\nG1 X10 Y5 F600\nG2 X20 Y5 I5 J0\nM2\n");
  const auto direct = runCli("canon " + program);
  const std::string piped = std::string("sh -c 'cat ") + program + " | " + ::isurface::test::cliProgram() + " canon /dev/stdin'";
  const auto throughPipe = isurface::test::runShell(piped);
  EXPECT_EQ(direct.exitCode, 0);
  EXPECT_EQ(throughPipe.exitCode, 0) << throughPipe.err;
  EXPECT_EQ(throughPipe.out, direct.out);
}

TEST(BoundedRuns, APickedSampleOutOfRangeIsAnErrorLikeAPickedLine) {
  const std::string program = writeScratch("pick.nc", "G21 G90\nG1 X10 Y5 F600\nM2\n");
  const std::string png = (scratchDir() / "pick.png").string();
  const auto negative = runCli("ui-snapshot " + program + " --pick-sample -1 -o " + png);
  EXPECT_EQ(negative.exitCode, 2) << negative.err;
  const auto beyond = runCli("ui-snapshot " + program + " --pick-sample 99999999 -o " + png);
  EXPECT_EQ(beyond.exitCode, 2) << beyond.err;
  EXPECT_NE(beyond.err.find("sample 99999999 is out of range"), std::string::npos) << beyond.err;
  EXPECT_FALSE(fs::exists(png));
}

TEST(BoundedRuns, AControlByteInAnInputIsShownNotPassedOn) {
  // A NUL in a cell once cut the message short where C strings end, and an escape sequence went
  // to the terminal as it was.
  static const char kTrace[] = "x,y,z\n0,0,0\n1,2\0\x1b[2J,3\n";
  const std::string trace = writeScratch("nul.csv", std::string(kTrace, sizeof kTrace - 1));
  const auto r = runCli("import csv " + trace + " --map x=x,y=y,z=z -o " + (scratchDir() / "nul.biip").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nul.csv:3:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2\\x00\\x1b[2J"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("is not a number"), std::string::npos) << r.err;
}
