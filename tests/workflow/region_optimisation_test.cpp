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
  EXPECT_GT(r.regionBefore.samples, 10u);
  EXPECT_GT(r.regionAfter.samples, 10u);
  EXPECT_GT(r.regionBefore.speedFluctuation, 0.0);
  EXPECT_GT(r.regionAfter.speedFluctuation, 0.0);
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

TEST(regionOptimisation, ACandidateWorseThanTheProgramIsNotKept) {
  // One pass re-fitted alone runs at other speeds than its unchanged neighbours: the region's
  // inconsistency between passes grows, so the candidate is reported and not kept.
  const RegionOptimisation r = optimise(*passOfLine(transition().before, 150));
  EXPECT_FALSE(r.kept);
  EXPECT_NE(r.reason.find("inconsistency between passes"), std::string::npos) << r.reason;
  EXPECT_GT(r.regionAfter.inconsistencyP99, r.regionBefore.inconsistencyP99 * (1 + kWorseningAllowed));
  EXPECT_NE(regionSummary(r).find("Not kept"), std::string::npos);
  EXPECT_TRUE(worsening(r).has_value());
}

TEST(regionOptimisation, ACandidateNoWorseOnAnyFigureIsKept) {
  // The worst region of another sample, as --auto takes it: better on every figure, not slower.
  const std::string path = sourcePath("samples/wuzhishan.nc");
  const Program program = readProgram(path);
  const SurfaceRun before = surfaceRun(std::make_shared<const Trajectory>(simulateRun(program, defaultMachine())), &program);
  const ChosenRegion worst = worstRegion(before, path);
  RegionRequest request;
  request.lines = worst.lines;
  request.box = std::make_pair(worst.lower, worst.upper);
  const RegionOptimisation r = optimiseRegion(readFile(path), program, before, defaultMachine(), request);
  EXPECT_TRUE(r.kept) << r.reason;
  EXPECT_FALSE(worsening(r).has_value());
  EXPECT_LE(r.timeAfter, r.timeBefore);
  EXPECT_LT(r.regionAfter.inconsistencyP99, r.regionBefore.inconsistencyP99);
}

TEST(regionOptimisation, TheFiguresJudgeEveryFigureByTheSameRule) {
  QualityFigures before;
  before.speedFluctuation = 100, before.inconsistencyP99 = 200, before.inconsistencyMean = 20, before.jerkP99 = 1e4,
  before.deviationP99 = 5;
  EXPECT_EQ(worseFigure(before, before, kWorseningAllowed), "");
  QualityFigures slightly = before;
  slightly.deviationP99 = 5.09;  // +1.8 %
  EXPECT_EQ(worseFigure(before, slightly, kWorseningAllowed), "");
  for (double QualityFigures::*figure : {&QualityFigures::speedFluctuation, &QualityFigures::inconsistencyP99,
                                         &QualityFigures::inconsistencyMean, &QualityFigures::jerkP99,
                                         &QualityFigures::deviationP99}) {
    QualityFigures worse = before;
    worse.*figure *= 1.03;
    EXPECT_NE(worseFigure(before, worse, kWorseningAllowed), "");
  }
}

TEST(regionOptimisation, ACandidateThatWritesAnEarlierOnesProgramIsNotSimulatedAgain) {
  // Every interval of the transition's worst region is planned at the programmed feed, so the
  // feeds planned across passes change nothing: those candidates are the paper's plan again.
  const ChosenRegion worst = worstRegion(transition().before, "transition-surface.nc");
  RegionRequest request;
  request.lines = worst.lines;
  request.box = std::make_pair(worst.lower, worst.upper);
  const RegionOptimisation r =
      optimiseRegion(transition().text, transition().program, transition().before, defaultMachine(), request);
  ASSERT_FALSE(r.candidates.empty());
  for (const RegionOptimisation::Outcome& c : r.candidates)
    EXPECT_EQ(c.plan.find("planned across passes"), std::string::npos) << c.plan;
  EXPECT_EQ(r.plan, r.candidates.front().plan);  // none kept: the first is reported
}
