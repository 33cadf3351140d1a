// Comparing two runs of a program: alignment by line and arc length, the figures per line and
// range, lines only one run has, degenerate lines, and the errors.
#include <gtest/gtest.h>

#include <cmath>

#include "isurface/base/diagnostic.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/analysis/run_comparison.h"
#include "isurface/nc/simulator.h"
#include "isurface/nc/sample_trajectory.h"

namespace isurface {
namespace {

// Ten moves of about 20 mm (lines 2-11) zig-zagging across X, 1 mm up in Y each; lines 7-11
// at `lateFeed`.
std::string zigzag(int lateFeed) {
  std::string text = "G21 G90 G64\n";
  for (int k = 0; k < 10; ++k) {
    text += "G1 X" + std::to_string(k % 2 == 0 ? 20 : 0) + " Y" + std::to_string(k) +
            (k == 0 ? " F1200" : k == 5 ? " F" + std::to_string(lateFeed) : "") + "\n";
  }
  return text;
}

Trajectory simulateText(const std::string& text, const std::string& name) {
  InterpretResult r = interpretGcode(text, name);
  EXPECT_TRUE(r.ok());
  SampleBuffer buffer;
  const Machine machine = defaultMachine();
  simulate(r.program, machine, buffer);
  Trajectory t = trajectoryFromSamples(buffer.data, machine.cycle, name);
  t.hasLine = true;
  return t;
}

void expectFinite(const DifferenceFigures& f) {
  for (double v : {f.timeA, f.timeB, f.timeDifference, f.lengthA, f.lengthB, f.meanSpeedDifference,
                   f.maxSpeedDifference, f.maxPositionDistance, f.maxPathDistance})
    EXPECT_TRUE(std::isfinite(v));
}

// Keeps only the samples for which `keep(i)` holds, in every channel the tests use.
template <class Keep>
Trajectory filtered(const Trajectory& t, Keep keep) {
  Trajectory out = t;
  out.time.clear(), out.line.clear(), out.x.clear(), out.y.clear(), out.z.clear(), out.block.clear();
  out.fbOffsetX.clear(), out.fbOffsetY.clear(), out.fbOffsetZ.clear(), out.feed.clear(), out.extra.clear();
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!keep(i)) continue;
    out.time.push_back(t.timeAt(i)), out.line.push_back(t.line[i]);
    out.x.push_back(t.x[i]), out.y.push_back(t.y[i]), out.z.push_back(t.z[i]);
  }
  out.irregularTime = true;
  return out;
}

TEST(runComparison, aRunAgainstItselfDiffersByNothing) {
  const Trajectory a = simulateText(zigzag(1200), "a.nc");
  const RunComparison c = compareRuns(a, a);
  ASSERT_EQ(c.lines.size(), 10u);
  EXPECT_TRUE(c.onlyInA.empty() && c.onlyInB.empty());
  EXPECT_DOUBLE_EQ(c.total.timeDifference, 0.0);
  EXPECT_DOUBLE_EQ(c.total.maxSpeedDifference, 0.0);
  EXPECT_DOUBLE_EQ(c.total.maxPositionDistance, 0.0);
  EXPECT_NEAR(c.total.maxPathDistance, 0.0, 1e-12);
  EXPECT_NEAR(c.total.lengthA, 20.0 + 9 * std::hypot(20.0, 1.0), 1.5);  // mm, less where corners are rounded
  EXPECT_DOUBLE_EQ(c.coverageA, 1.0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a.line[i] == 0) continue;
    EXPECT_EQ(c.speedDifference[i], 0.0f) << i;
    EXPECT_EQ(c.timeDifference[i], 0.0f) << i;
  }
  // Equal lines are one pattern: ranges only end at the line limit.
  EXPECT_EQ(c.ranges.size(), 1u);
}

TEST(runComparison, aRunTakingTwiceAsLongIsSlowerEverywhereByHalfItsSpeed) {
  const Trajectory a = simulateText(zigzag(1200), "a.nc");
  Trajectory b = a;
  // A simulation's samples are regular (no time stored): the cycle is their time.
  ASSERT_TRUE(b.time.empty());
  b.cycle *= 2;
  const RunComparison c = compareRuns(a, b);
  EXPECT_NEAR(c.total.timeB, 2 * c.total.timeA, 1e-9);
  EXPECT_NEAR(c.durationB, 2 * c.durationA, 1e-9);
  EXPECT_NEAR(c.total.maxPositionDistance, 0.0, 1e-9);
  // At every place B is at half of A's speed: the difference is minus half of A's speed.
  EXPECT_NEAR(c.total.maxSpeedDifference, -0.5 * 1200, 12);  // mm/min
  for (const LineDifference& line : c.lines) {
    EXPECT_NEAR(line.figures.timeDifference, line.figures.timeA, 1e-9);
    EXPECT_LT(line.figures.meanSpeedDifference, -100);
  }
  // The lag at the last sample with a line is A's whole duration.
  std::size_t last = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a.line[i] != 0) last = i;
  EXPECT_NEAR(c.timeDifference[last], c.durationA, 1e-3);
}

TEST(runComparison, aSlowerFeedOnSomeLinesShowsThereAndOnlyThere) {
  const Trajectory a = simulateText(zigzag(1200), "a.nc");
  const Trajectory b = simulateText(zigzag(600), "b.nc");  // lines 7-11 at half the feed
  const RunComparison c = compareRuns(a, b);
  ASSERT_EQ(c.lines.size(), 10u);
  for (const LineDifference& line : c.lines) {
    if (line.line <= 5) {
      EXPECT_NEAR(line.figures.timeDifference, 0.0, 0.002) << line.line;
      EXPECT_NEAR(line.figures.maxPositionDistance, 0.0, 1e-6) << line.line;
    } else if (line.line >= 8) {
      // 20 mm at 600 instead of 1200 mm/min: about a second more, half the speed mid-line.
      EXPECT_NEAR(line.figures.timeDifference, 1.0, 0.1) << line.line;
      EXPECT_NEAR(line.figures.meanSpeedDifference, -600, 120) << line.line;
    }
  }
  EXPECT_NEAR(c.total.timeDifference, 5.0, 0.3);
  const std::vector<std::size_t> worst = c.worstRanges(ComparisonQuantity::Time, 1);
  ASSERT_EQ(worst.size(), 1u);
  const RangeDifference& range = c.ranges[worst.front()];
  EXPECT_GE(range.firstLine, 6u);
  EXPECT_EQ(range.lastLine, 11u);
  EXPECT_NEAR(range.figures.timeDifference, 5.0, 0.3);
  EXPECT_EQ(c.worstRanges(ComparisonQuantity::Speed, 100).size(), c.ranges.size());
}

TEST(runComparison, linesOnlyOneRunHasAreReportedAndMergedIntoTheLineBefore) {
  const Trajectory a = simulateText(zigzag(1200), "a.nc");
  // B lost line 5 and has samples of a line 40 that A never reached.
  Trajectory b = filtered(a, [&](std::size_t i) { return a.line[i] != 5; });
  b.line.resize(b.size() - 10);
  b.line.append(40, 10);
  const RunComparison c = compareRuns(a, b);
  ASSERT_EQ(c.onlyInA.size(), 1u);
  EXPECT_EQ(c.onlyInA.front().line, 5u);
  EXPECT_EQ(c.onlyInA.front().mergedInto, 4u);
  EXPECT_GT(c.onlyInA.front().time, 0.5);  // s, 20 mm at 1200 mm/min
  ASSERT_EQ(c.onlyInB.size(), 1u);
  EXPECT_EQ(c.onlyInB.front().line, 40u);
  EXPECT_EQ(c.onlyInB.front().mergedInto, 11u);
  EXPECT_EQ(c.onlyInB.front().samples, 10u);
  EXPECT_LT(c.coverageA, 0.95);
  for (const LineDifference& line : c.lines) EXPECT_NE(line.line, 5u);
  // The totals are the whole runs: A's line 5 is in them, though B has no time for it.
  EXPECT_NEAR(c.total.timeA, c.durationA, 2 * a.cycle);
  EXPECT_NEAR(c.total.timeB, c.durationB, 2 * b.cycle);
}

// A blending control (LinuxCNC) runs a short line inside the blend of its neighbours and reports
// its samples under the line before: the same motion, the same total time.
TEST(runComparison, aLineRunInsideABlendCostsTheTotalNothing) {
  const Trajectory a = simulateText(zigzag(1200), "simulated.nc");
  Trajectory b = a;
  b.line.clear();
  for (std::size_t i = 0; i < a.size(); ++i) b.line.push_back(a.line[i] == 5 ? 4u : a.line[i]);
  const RunComparison c = compareRuns(a, b);
  EXPECT_NEAR(c.total.timeDifference, 0.0, 2 * a.cycle);
  EXPECT_NEAR(c.total.timeA, c.durationA, 2 * a.cycle);
  ASSERT_EQ(c.onlyInA.size(), 1u);
  EXPECT_EQ(c.onlyInA.front().mergedInto, 4u);
  for (const LineDifference& line : c.lines) EXPECT_NEAR(line.figures.timeDifference, 0.0, 2 * a.cycle) << line.line;
}

TEST(runComparison, degenerateLinesGiveFiniteFigures) {
  // Line 1: one sample. Line 2: the tool standing still (zero length). Line 3: a move.
  Trajectory a;
  a.hasLine = true;
  const double xs[] = {0, 0, 0, 0, 0.1, 0.2, 0.3};
  const std::uint32_t lines[] = {1, 2, 2, 2, 3, 3, 3};
  for (int i = 0; i < 7; ++i) {
    a.time.push_back(0.001 * i), a.line.push_back(lines[i]);
    a.x.push_back(xs[i]), a.y.push_back(0), a.z.push_back(0);
  }
  Trajectory b = filtered(a, [](std::size_t i) { return i != 2; });  // a dwell one cycle shorter
  for (std::size_t i = 0; i < b.size(); ++i) b.time[i] = 0.001 * double(i);
  const RunComparison c = compareRuns(a, b);
  ASSERT_EQ(c.lines.size(), 3u);
  for (const LineDifference& line : c.lines) expectFinite(line.figures);
  expectFinite(c.total);
  EXPECT_NEAR(c.lines[1].figures.timeDifference, -0.001, 1e-12);
  EXPECT_DOUBLE_EQ(c.lines[1].figures.lengthA, 0.0);
}

TEST(runComparison, feedbackIsComparedWhenBothRunsHaveIt) {
  const Trajectory a = simulateText(zigzag(1200), "a.nc");
  ASSERT_TRUE(a.hasFeedback());
  Trajectory b = a;
  for (float& y : b.fbOffsetY) y += 0.01f;  // mm
  const RunComparison c = compareRuns(a, b);
  ASSERT_TRUE(c.feedbackCompared);
  ASSERT_TRUE(c.total.maxFeedbackDistance.has_value());
  EXPECT_NEAR(*c.total.maxFeedbackDistance, 0.01, 1e-8);  // offsets are floats: 1e-7 of themselves
  EXPECT_NEAR(c.total.maxPositionDistance, 0.0, 1e-12);
  b.fbOffsetX.clear(), b.fbOffsetY.clear(), b.fbOffsetZ.clear();
  EXPECT_FALSE(compareRuns(a, b).total.maxFeedbackDistance.has_value());
}

TEST(runComparison, runsWithoutCommonLinesOrWithoutLinesAreRefused) {
  const Trajectory a = simulateText(zigzag(1200), "a.nc");
  Trajectory b = a;
  b.source = "b.biip";
  std::vector<std::uint32_t> lines = b.line.toVector();
  for (std::uint32_t& line : lines) line = line ? line + 1000 : 0;
  b.line = lines;
  try {
    compareRuns(a, b);
    FAIL() << "no common lines accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("b.biip"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("shares no G-code line"), std::string::npos) << e.what();
  }
  Trajectory noLines = a;
  noLines.source = "trace.biip";
  noLines.hasLine = false;
  noLines.line.assign(noLines.size(), 0);
  EXPECT_THROW(compareRuns(a, noLines), InputError);
  EXPECT_THROW(compareRuns(noLines, a), InputError);
}

TEST(runComparison, quantityNamesRoundTrip) {
  for (ComparisonQuantity q : {ComparisonQuantity::Speed, ComparisonQuantity::Position, ComparisonQuantity::Time})
    EXPECT_EQ(parseComparisonQuantity(comparisonQuantityName(q)), q);
  EXPECT_FALSE(parseComparisonQuantity("jerk").has_value());
}

}  // namespace
}  // namespace isurface

namespace isurface {
namespace {

// A run at one point on one line: `n` samples, 1 ms apart.
Trajectory standing(std::size_t n, std::uint32_t line) {
  Trajectory t;
  t.source = "standing";
  t.cycle = 0.001;
  t.hasLine = true;
  t.x.assign(n, 1.0), t.y.assign(n, 2.0), t.z.assign(n, 3.0);
  t.line.assign(n, line);
  t.time.resize(n);
  for (std::size_t i = 0; i < n; ++i) t.time[i] = 0.001 * double(i);
  return t;
}

TEST(runComparison, theLastLineNumberCostsWhatTheFirstDoes) {
  // Line 4294967295 once made an index of 4 G entries (bad_alloc).
  const Trajectory a = standing(100, 0xffffffffu);
  const RunComparison c = compareRuns(a, a);
  ASSERT_EQ(c.lines.size(), 1u);
  EXPECT_EQ(c.lines.front().line, 0xffffffffu);
}

TEST(runComparison, aMillionSamplesStandingAtOnePointAreComparedInLinearTime) {
  // Every sample of B within the search radius of every sample of A once made this quadratic
  // (35 s for 147 thousand samples; a million took over half an hour).
  const Trajectory a = standing(1000000, 7);
  const RunComparison c = compareRuns(a, a);
  ASSERT_EQ(c.lines.size(), 1u);
  EXPECT_EQ(c.lines.front().figures.maxPathDistance, 0.0);
}

}  // namespace
}  // namespace isurface
