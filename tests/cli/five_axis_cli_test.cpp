// Five-axis programs on the command line: canon lists A, B and C with every move as LinuxCNC's
// rs274 reads them; a machine without rotary axes refuses them with the first line that turns
// one; the five-axis machine's dump holds the tip, the rotary axes, the joints and the tool axis.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "image_compare.h"
#include "scratch_files.h"
#include "test_support.h"

namespace isurface {
namespace {

using test::runCli;
using test::scratchDir;

// Pixels of the tool axis strokes' dark blue (0.05, 0.1, 0.35) and near it.
std::size_t darkBluePixels(const std::string& png) {
  const test::Image image = test::readPng(png);
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const unsigned char* p = image.at(x, y);
      count += p[2] > 60 && p[2] < 140 && p[0] < 50 && p[1] < 60 && p[2] > p[0] + 30;
    }
  return count;
}

std::string program(const std::string& name) {
  return std::string(test::sourceDir()) + "/tests/data/linuxcnc-2.9-xyzbc-trt/" + name + ".ngc";
}

TEST(fiveAxisCli, CanonListsTheRotaryAxesOfEveryMove) {
  const auto r = runCli("canon " + program("rotary_only"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // G1 C90 at F2000 (line 8 of the file): the tip stays, C turns.
  EXPECT_NE(r.out.find("G1 10.0000 5.0000 10.0000 2000.0000 A0.0000 B20.0000 C90.0000\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" A0.0000 B-40.0000 C270.0000\n"), std::string::npos) << r.out;
  // Before the first rotary word, lines are as for a three-axis program.
  std::istringstream lines(r.out);
  std::string first;
  std::getline(lines, first);
  EXPECT_EQ(first.find(" A"), std::string::npos) << first;
  // A three-axis program lists no rotary axes at all.
  const auto plain = runCli("canon " + std::string(test::sourceDir()) + "/samples/transition-surface.nc");
  EXPECT_EQ(plain.out.find(" A0.0000"), std::string::npos);
}

// A machine without rotary axes cannot run a program that turns them: refused with the line and
// what to give instead, never the tip alone.
TEST(fiveAxisCli, RotaryMotionOnAMachineWithoutRotaryAxesIsRefusedWithItsLine) {
  const std::string dump = (scratchDir() / "swarf.biip").string();
  const auto r = runCli("simulate " + program("swarf_bc") + " -o " + dump);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("swarf_bc.ngc:8:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the machine has no rotary axes"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dump));
}

// On the five-axis machine the dump holds the tool tip, the rotary axes and the joints.
TEST(fiveAxisCli, SimulatingOnTheFiveAxisMachineWritesTheTipTheRotaryAxesAndTheJoints) {
  const std::string dump = (scratchDir() / "swarf.biip").string();
  const auto r = runCli("simulate " + program("swarf_bc") + " --machine " + std::string(test::sourceDir()) +
                        "/resources/machines/linuxcnc-xyzbc-trt.json -o " + dump);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto info = runCli("info " + dump);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  for (const char* channel : {"\"x\"", "\"b\"", "\"c\"", "\"joint_x\"", "\"joint_y\"", "\"joint_z\"", "\"joint_b\"", "\"joint_c\""})
    EXPECT_NE(info.out.find(channel), std::string::npos) << channel << "\n" << info.out;
}

// The tool axis is drawn along a five-axis run (dark strokes over the picture), and asked of a
// run without one it is refused with what is missing.
TEST(fiveAxisCli, RenderDrawsTheToolAxisOfAFiveAxisRunAndRefusesItElsewhere) {
  const std::string machine = " --machine " + std::string(test::sourceDir()) + "/resources/machines/linuxcnc-xyzbc-trt.json";
  const std::string plain = (scratchDir() / "plain.png").string(), axes = (scratchDir() / "axes.png").string();
  const auto without = runCli("render " + program("hemisphere_long") + machine + " --gap-limit 10 --size 400x300 -o " + plain);
  ASSERT_EQ(without.exitCode, 0) << without.err;
  const auto with = runCli("render " + program("hemisphere_long") + machine + " --gap-limit 10 --tool-axis --size 400x300 -o " + axes);
  ASSERT_EQ(with.exitCode, 0) << with.err;
  EXPECT_GT(darkBluePixels(axes), darkBluePixels(plain) + 500);
  const auto threeAxis = runCli("render " + std::string(test::sourceDir()) +
                                "/tests/data/linuxcnc-2.9/arcs_of_every_size_g64.ngc --tool-axis -o " + plain);
  EXPECT_EQ(threeAxis.exitCode, 2);
  EXPECT_NE(threeAxis.err.find("no tool axis"), std::string::npos) << threeAxis.err;
}

// The optimiser re-fits the tip alone: a five-axis program is refused with its first rotary
// line, and nothing is written.
TEST(fiveAxisCli, OptimisingAFiveAxisProgramIsRefusedWithItsLine) {
  const std::string out = (scratchDir() / "optimised.ngc").string();
  const auto r = runCli("optimize " + program("swarf_bc") + " --machine " + std::string(test::sourceDir()) +
                        "/resources/machines/linuxcnc-xyzbc-trt.json --lines 8-20 -o " + out);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("swarf_bc.ngc:8:1: five-axis programs (A, B or C turn here) are not re-optimised"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace isurface
