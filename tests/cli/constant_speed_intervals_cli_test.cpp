// isurface-cli intervals: a program's sections, constant speed intervals and planned feeds as
// JSON, the same as the library finds; bad options refused.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "gcode_test_support.h"
#include "isurface/fitting/constant_speed_intervals.h"
#include "test_support.h"

namespace isurface {
namespace {

using gcodetest::interpret;

std::string writeProgram(const std::string& name, const std::string& text) {
  const std::string path = (test::scratchDir() / name).string();
  std::ofstream(path) << text;
  return path;
}

// Line 3 a 10 mm line, line 4 a quarter arc of radius 5, line 5 a 7 mm line, then a reversal.
const char* kSmallProgram =
    "G21 G90\nG0 X0 Y0 Z0\nG1 X10 F600\nG3 X15 Y5 I0 J5\nG1 Y12\nX16 Y13\nY1 F300\nM2\n";

TEST(constantSpeedIntervals, cliPrintsSectionsIntervalsAndFeeds) {
  const std::string path = writeProgram("intervals.ngc", kSmallProgram);
  const test::CommandResult r = test::runCli("intervals " + path + " --lines 3-5");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["sections"].size(), 1u);
  const auto& s = j["sections"][0];
  EXPECT_EQ(s["first_line"], 3);
  EXPECT_EQ(s["last_line"], 5);
  // The CLI reports exactly what the library finds on the same section.
  const auto sections = collectSections(interpret(kSmallProgram), 3, 5);
  ASSERT_EQ(sections.size(), 1u);
  const IntervalPartition part = partitionConstantSpeedIntervals(sections[0].points);
  const auto& intervals = s["intervals"];
  ASSERT_EQ(intervals.size(), part.intervals.size());
  ASSERT_EQ(s["characteristic_points"].size(), part.characteristic.size());
  for (std::size_t k = 0; k < part.intervals.size(); ++k) {
    EXPECT_EQ(intervals[k]["first"], part.intervals[k].first);
    EXPECT_EQ(intervals[k]["last"], part.intervals[k].last);
    EXPECT_NEAR(intervals[k]["avg_curvature_per_mm"].get<double>(), part.intervals[k].averageCurvature, 1e-12);
    EXPECT_LE(intervals[k]["planned_feed_mm_min"].get<double>(), 600.0);
  }
  const auto& points = s["characteristic_points"];
  EXPECT_FALSE(points.front()["inside"].get<bool>());
  EXPECT_FALSE(points.back()["inside"].get<bool>());
  // The whole program: the reversal on line 7 starts a second section.
  const test::CommandResult all = test::runCli("intervals " + path);
  ASSERT_EQ(all.exitCode, 0) << all.err;
  EXPECT_EQ(nlohmann::json::parse(all.out)["sections"].size(), 2u);
}

TEST(constantSpeedIntervals, cliRejectsBadInput) {
  const std::string path = writeProgram("intervals-bad.ngc", kSmallProgram);
  for (const char* args : {"--lines 5-3", "--lines x", "--lines 0-3", "--lines 1-2", "--lines 8-8",
                           "--err 0", "--err -1", "--dist-ratio 0", "--curv-ratio -2"}) {
    const test::CommandResult r = test::runCli("intervals " + path + " " + args);
    EXPECT_EQ(r.exitCode, 2) << args;
    EXPECT_NE(r.err.find("error"), std::string::npos) << args << ": " << r.err;
  }
}

}  // namespace
}  // namespace isurface
