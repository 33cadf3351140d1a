// isurface-cli analyze: the quality regions of the transition sample, at the pass ends and
// inside the passes, ranked by severity.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "control_machines.h"
#include "test_support.h"

using namespace isurface::test;

// On a control that brakes at chord junctions (the paper's NC system), the transition sample's
// passes disagree where they start and stop (zig-zag: one pass speeds up where its neighbour
// slows down) and in the transition: analyze tells the two apart, and the worst region inside
// the passes is the transition.
TEST(qualityRegions, AnalyzeFindsTheTransitionOfTheSample) {
  const std::string out = (scratchDir() / "analysis.json").string();
  const CommandResult r = runCli("analyze " + sourcePath("samples/transition-surface.nc") + " -o " + out +
                                 " --machine " + sourcePath(kMachineWithoutChordSmoothing));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("worst inside the passes at lines"), std::string::npos) << r.out;
  const nlohmann::json report = nlohmann::json::parse(readFile(out));
  ASSERT_GE(report["regions"].size(), 3u);
  const nlohmann::json* worst = nullptr;
  for (const auto& region : report["regions"]) {
    const double lowX = region["bounding_box"]["min"][0].get<double>(), highX = region["bounding_box"]["max"][0].get<double>();
    // The passes run from x = 0 to x = 80.
    EXPECT_EQ(region["at_pass_ends"].get<bool>(), highX < 3.0 || lowX > 77.0) << region.dump();
    if (!worst && !region["at_pass_ends"].get<bool>()) worst = &region;
  }
  ASSERT_NE(worst, nullptr);
  // The transition runs from x = 22 to x = 22 + 40 mm at most.
  EXPECT_GT((*worst)["bounding_box"]["min"][0].get<double>(), 20.0);
  EXPECT_LT((*worst)["bounding_box"]["max"][0].get<double>(), 62.0);
  EXPECT_GE(report["regions"][0]["severity"].get<double>(), report["regions"].back()["severity"].get<double>());
  EXPECT_EQ(runCli("analyze " + sourcePath("samples/transition-surface.nc") + " --speed-threshold 0 -o " + out).exitCode, 2);
}

// The default machine's control runs the transition's chords as the curve they sample: the
// passes still disagree where they start and stop, and nowhere inside them.
TEST(qualityRegions, ASmoothingControlLeavesTheTransitionWithoutMarks) {
  const std::string out = (scratchDir() / "analysis-smoothed.json").string();
  const CommandResult r = runCli("analyze " + sourcePath("samples/transition-surface.nc") + " -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.find("worst inside the passes at lines"), std::string::npos) << r.out;
  const nlohmann::json report = nlohmann::json::parse(readFile(out));
  ASSERT_GE(report["regions"].size(), 1u);
  for (const auto& region : report["regions"]) EXPECT_TRUE(region["at_pass_ends"].get<bool>()) << region.dump();
}
