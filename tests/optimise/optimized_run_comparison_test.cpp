// The runs before and after re-optimising a region, aligned by line groups: each re-fitted
// pass against the lines it replaced, every other line against itself shifted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/optimise/optimized_run_comparison.h"
#include "isurface/nc/simulator.h"
#include "isurface/nc/sample_trajectory.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

Trajectory simulated(const Program& program) {
  const Machine machine = defaultMachine();
  SampleBuffer buffer;
  simulate(program, machine, buffer);
  return trajectoryFromSamples(buffer.data, machine.cycle, program.source);
}

OptimizedPass pass(std::uint32_t first, std::uint32_t last, std::uint32_t newFirst, std::uint32_t newLast) {
  OptimizedPass p;
  p.firstLine = first, p.lastLine = last, p.newFirstLine = newFirst, p.newLastLine = newLast;
  return p;
}

const LineDifference* findLine(const RunComparison& c, std::uint32_t line) {
  const auto at = std::find_if(c.lines.begin(), c.lines.end(), [&](const LineDifference& d) { return d.line == line; });
  return at == c.lines.end() ? nullptr : &*at;
}

}  // namespace

TEST(optimizedRunComparison, KeysGroupPassesAndShiftTheLinesBetween) {
  OptimizeResult r;
  // Old lines 1-20; 5-8 became new lines 5-11 (+3), 12-14 became new 15-16 (-1 more: +2).
  r.passes = {pass(5, 8, 5, 11), pass(12, 14, 15, 16)};
  r.text = std::string(20 + 2, '\n');
  const OptimizedLineKeys keys = optimizedLineKeys(r);
  ASSERT_EQ(keys.after.size(), 23u);
  EXPECT_EQ(keys.before[4], 4u);
  EXPECT_EQ(keys.before[7], 5u);
  EXPECT_EQ(keys.before[13], 12u);
  EXPECT_EQ(keys.after[4], 4u);
  for (std::uint32_t line = 5; line <= 11; ++line) EXPECT_EQ(keys.after[line], 5u) << line;
  EXPECT_EQ(keys.after[12], 9u);
  EXPECT_EQ(keys.after[14], 11u);
  EXPECT_EQ(keys.after[15], 12u);
  EXPECT_EQ(keys.after[16], 12u);
  EXPECT_EQ(keys.after[17], 15u);
  EXPECT_EQ(keys.after[22], 20u);
}

TEST(optimizedRunComparison, TheTransitionSampleBeforeAndAfterMatchPassByPass) {
  const std::string path = sourcePath("samples/transition-surface.nc");
  const std::string text = readFile(path);
  const InterpretResult original = interpretGcode(text, path);
  ASSERT_TRUE(original.ok());
  const OptimizeResult optimized = optimizeRegion(text, original.program, LineRange{105, 400}, defaultMachine());
  ASSERT_GE(optimized.passes.size(), 3u);
  const InterpretResult reread = interpretGcode(optimized.text, "optimized.nc");
  ASSERT_TRUE(reread.ok()) << reread.errors.front().str();
  const Trajectory before = simulated(original.program), after = simulated(reread.program);

  const RunComparison c = compareOptimizedRuns(before, after, optimized);
  for (const OptimizedPass& p : optimized.passes) {
    const LineDifference* group = findLine(c, p.firstLine);
    ASSERT_NE(group, nullptr) << "pass at lines " << p.firstLine << "-" << p.lastLine;
    const DifferenceFigures& f = group->figures;
    EXPECT_GT(f.samplesA, 100u);
    EXPECT_EQ(f.comparedSamples, f.samplesA);
    EXPECT_LT(f.maxPathDistance, 0.01);  // mm: the new path follows the old one
    EXPECT_TRUE(std::isfinite(f.maxSpeedDifference) && std::isfinite(f.meanSpeedDifference));
    // Each of the pass's samples in the old run has its after-minus-before speed.
    for (std::size_t i = 0; i < before.size(); ++i) {
      if (before.line[i] >= p.firstLine && before.line[i] <= p.lastLine) {
        ASSERT_TRUE(std::isfinite(c.speedDifference[i])) << "sample " << i;
      }
    }
  }
  // The lines the passes replaced are not reported as the old run's alone, and nothing of the
  // new run is left unmatched.
  for (const UnmatchedLine& u : c.onlyInA)
    for (const OptimizedPass& p : optimized.passes)
      EXPECT_FALSE(u.line >= p.firstLine && u.line <= p.lastLine) << "line " << u.line;
  EXPECT_TRUE(c.onlyInB.empty());
  // The program after the region is the same: its lines match their shifted selves.
  const LineDifference* later = findLine(c, optimized.passes.back().lastLine + 200);
  ASSERT_NE(later, nullptr);
  EXPECT_LT(later->figures.maxPathDistance, 0.001);  // mm: only where the samples fall differs
  EXPECT_LT(c.total.maxPathDistance, 0.01);

  // Aligned line by line instead, the re-fitted lines cannot be matched.
  const RunComparison byLine = compareRuns(before, after);
  EXPECT_GT(byLine.total.maxPathDistance, 0.01);
}
