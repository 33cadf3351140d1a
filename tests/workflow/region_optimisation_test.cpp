// Re-optimising a region as `optimize` and the application's dialog both do it.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "isurface/workflow/region_optimisation.h"
#include "workflow_fixtures.h"

using namespace isurface;
using namespace isurface::test;

namespace {

struct Transition {
  std::string text;
  Program program;
  SurfaceRun before;
};

const Transition& transition() {
  static const Transition t = [] {
    Transition made;
    const std::string path = sourcePath("samples/transition-surface.nc");
    made.text = readFile(path);
    made.program = readProgram(path);
    made.before = surfaceRun(std::make_shared<const Trajectory>(simulateRun(made.program, defaultMachine())),
                             &made.program);
    return made;
  }();
  return t;
}

RegionOptimisation optimise(LineRange lines) {
  RegionRequest request;
  request.lines = lines;
  return optimiseRegion(transition().text, transition().program, transition().before, defaultMachine(), request);
}

}  // namespace

TEST(regionOptimisation, TheSelectedLinesPassIsTheWholePassHoldingIt) {
  const auto pass = passOfLine(transition().before, 150);
  ASSERT_TRUE(pass);
  EXPECT_LT(pass->first, 150u);
  EXPECT_GT(pass->last, 150u);
  // One pass, not pieces of three: the line before it and the one after it are elsewhere.
  const auto next = passOfLine(transition().before, pass->last + 2);
  ASSERT_TRUE(next);
  EXPECT_GT(next->first, pass->last);
  EXPECT_FALSE(passOfLine(transition().before, 1));  // the header is on no pass
}

TEST(regionOptimisation, ATypedRangeOfOnePassIsMeasuredNotReportedAsZero) {
  const LineRange lines = *passOfLine(transition().before, 150);
  const RegionOptimisation r = optimise(lines);
  EXPECT_GT(r.before.samples, 10u);
  EXPECT_GT(r.afterMetrics.samples, 10u);
  EXPECT_GT(r.before.speedFluctuation, 0.0);
  EXPECT_GT(r.afterMetrics.speedFluctuation, 0.0);
}

TEST(regionOptimisation, MachiningTimeIsTheSameFormulaOnBothSides) {
  const RegionOptimisation r = optimise({105, 400});
  const Trajectory& before = *transition().before.samples;
  EXPECT_DOUBLE_EQ(r.timeBefore, double(before.size() - 1) * before.cycle);
  EXPECT_DOUBLE_EQ(r.timeAfter, double(r.after.samples->size() - 1) * r.after.samples->cycle);
  EXPECT_LE(r.timeAfter, r.timeBefore + 0.01);
  EXPECT_LT(r.maxPathDistance, 0.01);  // mm
  EXPECT_NE(regionSummary(r).find("lines 105-400"), std::string::npos);
}

TEST(regionOptimisation, TheWorstRegionIsWholePassesWithTheDefectsBox) {
  const ChosenRegion worst = worstRegion(transition().before, "transition-surface.nc");
  EXPECT_LT(worst.lines.first, worst.lines.last);
  EXPECT_GT(worst.vertices, 0u);
  EXPECT_LT(worst.lower.x(), worst.upper.x());
}
