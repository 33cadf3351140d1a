// isurface-cli compare: the report and the map, bad inputs, and the LinuxCNC recording against
// our simulation of its program with its limits.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "test_support.h"

using namespace isurface::test;

namespace {

std::string scratch(const std::string& name) { return (scratchDir() / name).string(); }

std::string writeText(const std::string& name, const std::string& text) {
  const std::string path = scratch(name);
  std::ofstream(path) << text;
  return path;
}

std::string simulated(const std::string& program, const std::string& name, const std::string& machine = "") {
  const std::string out = scratch(name);
  const CommandResult r = runCli("simulate " + program + " -o " + out + (machine.empty() ? "" : " --machine " + machine));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return out;
}

}  // namespace

TEST(compareCli, aDumpAgainstItselfReportsNoDifferenceAndDrawsTheMap) {
  const std::string program = sourcePath("samples/transition-surface.nc");
  const std::string a = simulated(program, "ts-a.biip"), b = simulated(program, "ts-b.biip");
  const std::string json = scratch("ts.json"), png = scratch("ts.png");
  const CommandResult r = runCli("compare " + a + " " + b + " --gcode " + program + " -o " + json + " --png " + png);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(readFile(json));
  EXPECT_EQ(report["totals"]["time_difference_s"].get<double>(), 0.0);
  EXPECT_EQ(report["totals"]["max_speed_difference_mm_min"].get<double>(), 0.0);
  EXPECT_EQ(report["totals"]["max_position_distance_mm"].get<double>(), 0.0);
  EXPECT_TRUE(report["only_in_a"].empty());
  EXPECT_GT(report["common_lines"].get<int>(), 1000);
  EXPECT_TRUE(report["totals"]["max_feedback_distance_mm"].is_number());  // simulations have feedback
  EXPECT_GT(std::filesystem::file_size(png), 10000u);
  EXPECT_NE(r.out.find("B - A +0.000 s"), std::string::npos) << r.out;
}

TEST(compareCli, aSlowerRunShowsItsTimeAndSpeedDifference) {
  const std::string fast = writeText("fast.nc", "G21 G90\nG1 X50 F3000\nG1 X50 Y2\nG1 X0 Y2\n");
  const std::string slow = writeText("slow.nc", "G21 G90\nG1 X50 F1500\nG1 X50 Y2\nG1 X0 Y2\n");
  const std::string json = scratch("slow.json");
  const CommandResult r = runCli("compare " + simulated(fast, "fast.biip") + " " + simulated(slow, "slow.biip") +
                                 " --quantity time -o " + json);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(readFile(json));
  // 102 mm at half the feed: 2.04 s more less what the faster run loses accelerating; the two
  // 50 mm lines half as fast mid-line.
  EXPECT_NEAR(report["totals"]["time_difference_s"].get<double>(), 1.97, 0.07);
  for (const auto& line : report["lines"]) {
    if (line["line"] == 3) continue;  // the 2 mm step-over barely reaches either feed
    EXPECT_NEAR(line["mean_speed_difference_mm_min"].get<double>(), -1500, 250) << line.dump();
  }
  EXPECT_EQ(report["ranked_by"], "time");
  EXPECT_EQ(report["worst_ranges"][0]["lines"][1], 4);
}

TEST(compareCli, badInputsExitWithTwoAndWriteNothing) {
  const std::string a = simulated(writeText("one.nc", "G1 X10 F1000\nG1 X20\n"), "one.biip");
  const std::string other = simulated(writeText("other.nc", "(a)\n(b)\n(c)\nG1 X10 F1000\nG1 X20\n"), "other.biip");
  const std::string notBiip = writeText("not.biip", "G1 X1\n");
  const std::string out = scratch("never.json"), png = scratch("never.png");
  struct Case {
    std::string args, expected;
  };
  const Case cases[] = {
      {a + " " + scratch("missing.biip"), "missing.biip"},
      {a + " " + notBiip, "not.biip"},
      {a + " " + other, "shares no G-code line"},
      {a + " " + a + " --quantity jerk", "unknown quantity"},
      {a + " " + a + " --range 5:1", "5:1"},
      {a + " " + a + " --gap-limit 0", "--gap-limit: 0 must be above 0"},
      {a + " " + a + " --cmap nosuch", "nosuch"},
      {a + " " + a + " --pattern spiral", "spiral"},
  };
  for (const Case& c : cases) {
    const CommandResult r = runCli("compare " + c.args + " -o " + out + " --png " + png);
    EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(fileExists(out)) << c.args;
    EXPECT_FALSE(fileExists(png)) << c.args;
  }
}

// Two programs whose lines have the same numbers but lie elsewhere: compared line by line their
// figures would mean nothing.
TEST(compareCli, runsOfDifferentProgramsAreRefusedUnlessForced) {
  const std::string a = simulated(writeText("here.nc", "G1 X10 F1000\nG1 X20\nG1 X30\n"), "here.biip");
  const std::string b = simulated(writeText("there.nc", "G1 Y50 F1000\nG1 Y60\nG1 Y70\n"), "there.biip");
  const std::string out = scratch("different.json");
  const CommandResult refused = runCli("compare " + a + " " + b + " -o " + out);
  EXPECT_EQ(refused.exitCode, 2);
  EXPECT_NE(refused.err.find("is not a run of"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--force"), std::string::npos) << refused.err;
  EXPECT_FALSE(fileExists(out));
  EXPECT_EQ(runCli("compare " + a + " " + b + " -o " + out + " --force").exitCode, 0);
  EXPECT_TRUE(fileExists(out));
}

// The program given with --gcode names the runs' lines in the report: one that neither ran is
// refused as another dump is.
TEST(compareCli, aProgramNeitherRunRanIsRefusedUnlessForced) {
  const std::string here = writeText("here-again.nc", "G1 X10 F1000\nG1 X20\nG1 X30\n");
  const std::string a = simulated(here, "here-a.biip"), b = simulated(here, "here-b.biip");
  const std::string other = writeText("elsewhere.nc", "G1 Y50 F1000\nG1 Y60\nG1 Y70\n");
  const std::string out = scratch("wrong-program.json");
  const CommandResult refused = runCli("compare " + a + " " + b + " -o " + out + " --gcode " + other);
  EXPECT_EQ(refused.exitCode, 2) << refused.err;
  EXPECT_NE(refused.err.find("elsewhere.nc: is not the program"), std::string::npos) << refused.err;
  EXPECT_FALSE(fileExists(out));
  EXPECT_EQ(runCli("compare " + a + " " + b + " -o " + out + " --gcode " + here).exitCode, 0);
}

TEST(compareCli, linuxcncRecordingAgainstOurSimulation) {
  const std::string recording = realdataPath("linuxcnc_test.halsampler.txt");
  const std::string program = realdataPath("linuxcnc_test.ngc");
  ISURFACE_SKIP_WITHOUT_REALDATA(recording, program);
  const std::string trace = scratch("lcnc.biip");
  ASSERT_EQ(runCli("import halsampler " + recording + " -o " + trace).exitCode, 0);
  const std::string sim = simulated(program, "lcnc-sim.biip", sourcePath("resources/machines/linuxcnc-sim.json"));
  const std::string json = scratch("lcnc.json"), png = scratch("lcnc.png");
  const CommandResult r = runCli("compare " + trace + " " + sim + " --gcode " + program + " -o " + json + " --png " +
                                 png + " --gap-limit 3 --pattern direction-parallel --view top");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(readFile(json));
  // Every line of the program that moves is in both runs, and nearly every sample is on them.
  EXPECT_GE(report["common_lines"].get<int>(), 250);
  EXPECT_TRUE(report["only_in_a"].empty());
  EXPECT_TRUE(report["only_in_b"].empty());
  EXPECT_GT(report["run_a"]["line_coverage"].get<double>(), 0.99);
  // The machine's linuxcnc-2.9 control agrees with LinuxCNC's planner within 2 % in total and
  // blends the rectangle's corners as it does; the worst range is where lines meet arcs at an
  // angle (docs/controls.md).
  const double percent = report["totals"]["time_difference_percent"].get<double>();
  EXPECT_GT(percent, -2.0);
  EXPECT_LT(percent, 2.0);
  const double pathDistance = report["totals"]["max_path_distance_mm"].get<double>();
  EXPECT_LT(pathDistance, 1.0);
  const auto& worst = report["worst_ranges"][0];
  EXPECT_GE(worst["lines"][1].get<int>(), 246) << worst.dump();
  EXPECT_GT(std::filesystem::file_size(png), 10000u);
}
