// Re-optimising a region as `optimize` and the application's dialog both do it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

#include <fmt/format.h>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/optimise/polyline_distance.h"
#include "isurface/workflow/region_optimisation.h"
#include "cam_style_transition.h"
#include "control_machines.h"
#include "workflow_fixtures.h"

using namespace isurface;
using namespace isurface::test;

// The optimiser's flow is shown on a control that brakes at chord junctions, as the paper's NC
// system does: the default machine's control runs these chords smoothly and leaves it little to do.
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
    made.before = surfaceRun(std::make_shared<const Trajectory>(simulateRun(made.program, machineWithoutChordSmoothing())),
                             &made.program);
    return made;
  }();
  return t;
}

RegionOptimisation optimise(LineRange lines) {
  RegionRequest request;
  request.lines = lines;
  return optimiseRegion(transition().text, transition().program, transition().before, machineWithoutChordSmoothing(), request);
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
  EXPECT_TRUE(whyNotKept(r).has_value());
}

TEST(regionOptimisationLong, ACandidateNoWorseOnAnyFigureIsKept) {
  // The worst region of another sample, as --auto takes it: better on every figure, not slower.
  const std::string path = sourcePath("samples/wuzhishan.nc");
  const Program program = readProgram(path);
  const SurfaceRun before = surfaceRun(std::make_shared<const Trajectory>(simulateRun(program, machineWithoutChordSmoothing())), &program);
  const ChosenRegion worst = worstRegion(before, path);
  RegionRequest request;
  request.lines = worst.lines;
  request.box = std::make_pair(worst.lower, worst.upper);
  const RegionOptimisation r = optimiseRegion(readFile(path), program, before, machineWithoutChordSmoothing(), request);
  EXPECT_TRUE(r.kept) << r.reason;
  EXPECT_FALSE(whyNotKept(r).has_value());
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

TEST(regionOptimisation, ACandidateThatHelpsByLessThanTwoPercentIsNotWritten) {
  QualityFigures figures;
  figures.samples = 1000, figures.speedFluctuation = 100, figures.inconsistencyP99 = 200, figures.inconsistencyMean = 20,
  figures.jerkP99 = 1e4, figures.deviationP99 = 5, figures.hasDeviation = true;
  RegionOptimisation r;
  r.regionBefore = r.regionAfter = r.wholeBefore = r.wholeAfter = figures;
  r.timeBefore = 100, r.timeAfter = 99;  // s: 1 % faster
  r.regionTimeBefore = 50, r.regionTimeAfter = 49.5;  // s: the region's lines 1 % faster
  r.maxPathDistance = 0.005;             // mm
  r.regionAfter.speedFluctuation = 99;   // 1 % evener
  const auto why = whyNotKept(r);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("it would help nothing"), std::string::npos) << *why;
  // A figure of the region 3 % better, or the time on its lines 2.1 % shorter, is a gain worth
  // writing.
  RegionOptimisation evener = r;
  evener.regionAfter.jerkP99 = 0.97e4;
  EXPECT_FALSE(whyNotKept(evener).has_value());
  RegionOptimisation faster = r;
  faster.timeAfter = 98.95, faster.regionTimeAfter = 48.95;
  EXPECT_FALSE(whyNotKept(faster).has_value());
  for (double QualityFigures::*figure : {&QualityFigures::speedFluctuation, &QualityFigures::inconsistencyP99,
                                         &QualityFigures::inconsistencyMean, &QualityFigures::jerkP99,
                                         &QualityFigures::deviationP99}) {
    QualityFigures better = figures, slightly = figures;
    better.*figure *= 0.97;
    slightly.*figure *= 0.99;
    EXPECT_NE(betterFigure(figures, better, kGainRequired), "");
    EXPECT_EQ(betterFigure(figures, slightly, kGainRequired), "");
  }
}

TEST(regionOptimisationLong, ACandidateThatWritesAnEarlierOnesProgramIsNotSimulatedAgain) {
  // Every interval of the transition's worst region is planned at the programmed feed, so the
  // feeds planned across passes change nothing: those candidates are the paper's plan again.
  const ChosenRegion worst = worstRegion(transition().before, "transition-surface.nc");
  RegionRequest request;
  request.lines = worst.lines;
  request.box = std::make_pair(worst.lower, worst.upper);
  std::vector<std::string> told;  // what a progress display is told, candidate by candidate
  request.onCandidate = [&told](const std::string& which) { told.push_back(which); };
  const RegionOptimisation r =
      optimiseRegion(transition().text, transition().program, transition().before, machineWithoutChordSmoothing(), request);
  ASSERT_FALSE(r.candidates.empty());
  for (const RegionOptimisation::Outcome& c : r.candidates)
    EXPECT_EQ(c.plan.find("planned across passes"), std::string::npos) << c.plan;
  EXPECT_EQ(r.candidates.front().plan, "each pass its own interval feeds");
  ASSERT_GE(told.size(), std::max<std::size_t>(2, r.candidates.size()));
  EXPECT_EQ(told.front(), "candidate 1: each pass its own interval feeds");
  EXPECT_EQ(told[1].rfind("candidate 2: ", 0), 0u) << told[1];
}

namespace {

// A relief raster whose points are 0.12 to 0.18 mm apart along X, F3000, as a CAM system samples
// a noisy height map: either they step up and down by 10 to 35 um in turn at every point, or
// each lies up to 25 um above or below the surface at random. The machine brakes at every
// point, whatever its feed.
std::string noisyRelief(bool zigZag) {
  std::string text = "G21 G90 G17\nG0 Z5\n";
  for (int pass = 0; pass < 12; ++pass) {
    const double y = 0.3 * pass;
    std::vector<std::pair<double, int>> stations;
    double x = 0;
    for (int i = 0; x <= 15.0; ++i, x += 0.12 + 0.015 * ((i * 7) % 5)) stations.emplace_back(x, i);
    if (pass % 2) std::reverse(stations.begin(), stations.end());
    for (std::size_t n = 0; n < stations.size(); ++n) {
      const auto [px, i] = stations[n];
      const std::uint32_t hash = (std::uint32_t(i) * 73856093u ^ std::uint32_t(pass) * 19349663u) * 2654435761u;
      const double unit = hash / 4294967295.0;  // 0..1
      const double noise = zigZag ? (i % 2 ? 1.0 : -1.0) * (0.010 + 0.025 * unit) : 0.05 * (unit - 0.5);
      const double z = 0.5 * std::sin(px / 5) * std::cos(y / 4) + noise;
      if (pass == 0 && n == 0) text += fmt::format("G0 X{:.4f} Y{:.4f}\nG1 Z{:.4f} F3000\n", px, y, z);
      else text += fmt::format("G1 X{:.4f} Y{:.4f} Z{:.4f}\n", px, y, z);
    }
  }
  return text + "G0 Z5\nM2\n";
}

RegionOptimisation optimiseWhole(const std::string& text, const Program& program) {
  const SurfaceRun before =
      surfaceRun(std::make_shared<const Trajectory>(simulateRun(program, machineWithoutChordSmoothing())), &program);
  RegionRequest request;
  request.lines = wholeProgramRegion(before, "relief.nc").lines;
  return optimiseRegion(text, program, before, machineWithoutChordSmoothing(), request);
}

}  // namespace

TEST(regionOptimisation, PointsDrawnTautRunFasterWithinTheirTube) {
  // The paper's plan brakes at the same corners (one feed per interval only slows it); the
  // points drawn taut turn less, and the machine runs the raster faster. Its passes then
  // disagree more (some steps are flattened away, others only lowered), which the loop reports.
  const std::string text = noisyRelief(true);
  const Program program = interpretGcode(text, "zig-zag-relief.nc").program;
  const RegionOptimisation r = optimiseWhole(text, program);
  const auto taut = std::find_if(r.candidates.begin(), r.candidates.end(), [](const RegionOptimisation::Outcome& c) {
    return c.plan.find("drawn taut") != std::string::npos;
  });
  ASSERT_NE(taut, r.candidates.end());
  EXPECT_LT(taut->timeAfter, 0.92 * r.timeBefore);
  EXPECT_NE(r.candidates.front().plan.find("each pass its own interval feeds"), std::string::npos);
  EXPECT_GT(r.candidates.front().timeAfter, r.timeBefore);

  OptimizeOptions options;
  options.shape = PathShape::DrawnTaut;
  options.programmedFeed = true;
  const OptimizeResult drawn = optimizeRegion(text, program, r.lines, machineWithoutChordSmoothing(), options);
  const Program after = interpretGcode(drawn.text, "zig-zag-relief.nc").program;
  auto cuttingPoints = [](const Program& p) {
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < p.moves.size(); ++i)
      if (p.moves[i].kind == MoveKind::Linear) points.push_back(p.moves[i].end);
    return points;
  };
  EXPECT_LE(polylineDistance(cuttingPoints(program), cuttingPoints(after)), options.maximumDeviation + 1e-4);
  EXPECT_NE(drawn.text.find("re-fitted: points drawn taut within 0.008 mm, feed F3000)"), std::string::npos);
}

TEST(regionOptimisation, ATautPathsSpeedPeaksAreTrimmedUntilNoFigureIsWorse) {
  // Drawn taut, the noisy relief runs far faster but its speed now peaks between the corners
  // left, and swings more than before; the feed capped below the top of those speeds keeps
  // most of the time won, and the speed swings no more than before.
  const std::string text = noisyRelief(false);
  const Program program = interpretGcode(text, "noisy-relief.nc").program;
  const RegionOptimisation r = optimiseWhole(text, program);
  ASSERT_TRUE(r.kept) << r.reason;
  EXPECT_EQ(r.plan.find("the program's feed capped at "), 0u) << r.plan;
  EXPECT_NE(r.plan.find("points drawn taut within 0.008 mm"), std::string::npos) << r.plan;
  EXPECT_NE(regionSummary(r).find(". Kept (balanced): not slower, no figure worse by more than 2 %"), std::string::npos);
  EXPECT_LT(r.timeAfter, 0.8 * r.timeBefore);
  EXPECT_LT(r.maxPathDistance, 0.01);
  const auto uncapped = std::find_if(r.candidates.begin(), r.candidates.end(), [](const RegionOptimisation::Outcome& c) {
    return c.plan.find("the program's feed kept, points drawn taut") == 0;
  });
  ASSERT_NE(uncapped, r.candidates.end());
  EXPECT_FALSE(uncapped->kept);
  EXPECT_NE(uncapped->reason.find("speed fluctuation"), std::string::npos) << uncapped->reason;
  EXPECT_LT(uncapped->timeAfter, r.timeAfter);  // the cap gives back a little of the time won
  EXPECT_LE(r.regionAfter.speedFluctuation, r.regionBefore.speedFluctuation * (1 + kWorseningAllowed));
  EXPECT_LT(r.regionAfter.inconsistencyP99, r.regionBefore.inconsistencyP99);
}

// A line range without a box: every candidate is measured where the first (the paper's steps)
// re-fits the path, so that the objective compares figures of the same samples.
TEST(regionOptimisation, WithoutABoxEveryCandidateIsMeasuredInTheFirstOnesBox) {
  const std::string text = noisyRelief(false);
  const Program program = interpretGcode(text, "scattered-relief.nc").program;
  const RegionOptimisation r = optimiseWhole(text, program);
  ASSERT_TRUE(r.kept) << r.reason;
  ASSERT_NE(r.plan, r.candidates.front().plan);  // a later candidate is the one chosen
  const OptimizeResult paper = optimizeRegion(text, program, r.lines, machineWithoutChordSmoothing(), OptimizeOptions{});
  EXPECT_EQ(r.lower, paper.fittedLower);
  EXPECT_EQ(r.upper, paper.fittedUpper);
  EXPECT_TRUE(r.result.fittedLower != r.lower || r.result.fittedUpper != r.upper)
      << "the chosen candidate re-fits the first one's box: the test shows nothing";
}

namespace {

// mm/s^2: the acceleration of a candidate's ramps, 0 without.
double rampsOf(const std::string& plan) {
  const std::size_t at = plan.find("ramps of ");
  return at == std::string::npos ? 0.0 : std::stod(plan.substr(at + 9));
}

}  // namespace

// The time the program's own braking loses is what the eased bends' ramps may spend, and it
// falls between the listed accelerations: on the CAM-style program some listed ramps keep the
// time and the next gentler do not, so the loop tries ramps between those two.
TEST(regionOptimisation, EasedRampsAreTriedAsGentleAsTheTimeAllows) {
  const std::string text = isurface::testing::camStyleTransitionProgram();
  const Program program = interpretGcode(text, "cam-style-transition.nc").program;
  const SurfaceRun before =
      surfaceRun(std::make_shared<const Trajectory>(simulateRun(program, machineWithoutChordSmoothing())), &program);
  RegionRequest request;
  request.lines = worstRegion(before, "cam-style-transition.nc").lines;
  const RegionOptimisation r = optimiseRegion(text, program, before, machineWithoutChordSmoothing(), request);
  ASSERT_TRUE(r.kept) << r.reason;
  EXPECT_LE(r.timeAfter, r.timeBefore);
  const std::vector<double> listed = {750, 500, 350, 250, 200, 150, 100};
  double gentlestListedInTime = 0;
  std::vector<double> between;
  for (const RegionOptimisation::Outcome& c : r.candidates) {
    if (c.plan.find("eased") == std::string::npos) continue;
    const double ramps = rampsOf(c.plan);
    const bool inTime = c.timeAfter <= r.timeBefore + 0.0005;  // half the 1 ms cycle
    if (std::find(listed.begin(), listed.end(), ramps) == listed.end()) between.push_back(ramps);
    else if (inTime && (gentlestListedInTime == 0 || ramps < gentlestListedInTime)) gentlestListedInTime = ramps;
  }
  ASSERT_GT(gentlestListedInTime, 0);
  const auto next = std::find(listed.begin(), listed.end(), gentlestListedInTime) + 1;
  ASSERT_NE(next, listed.end()) << "the gentlest ramps listed keep the time: nothing lies between";
  ASSERT_FALSE(between.empty());
  for (const double ramps : between) {
    EXPECT_LT(ramps, gentlestListedInTime);
    EXPECT_GT(ramps, *next);
  }
}

namespace {

// Zig-zag passes along X, one at each of `ys`, F2500, N numbers: over the CAM-style profile
// (plane, fillet by a chord tolerance, slope) where `bent` says so, else a plane of one move.
std::string rasterAt(const std::vector<double>& ys, const std::function<bool(double)>& bent, std::string& text, int& n) {
  isurface::testing::CamStyleTransition part;
  for (std::size_t p = 0; p < ys.size(); ++p) {
    auto profile = bent(ys[p]) ? isurface::testing::camProfile(part, ys[p])
                               : std::vector<std::pair<double, double>>{{0.0, 0.0}, {part.length, 0.0}};
    if (p % 2) std::reverse(profile.begin(), profile.end());
    const auto [x0, z0] = profile.front();
    if (p == 0) text += fmt::format("N{} G0 Z30.\nN{} G0 X{:.4f} Y{:.4f}\nN{} G1 Z{:.4f} F800.\n", n, n + 1, x0, ys[p], n + 2, z0), n += 3;
    else text += fmt::format("N{} G1 X{:.4f} Y{:.4f} Z{:.4f}\n", n++, x0, ys[p], z0);
    for (std::size_t k = 1; k < profile.size(); ++k)
      text += fmt::format("N{} G1 X{:.4f} Z{:.4f}{}\n", n++, profile[k].first, profile[k].second, k == 1 ? " F2500." : "");
  }
  return text;
}

}  // namespace

// A pass left as it was beside one re-planned runs at its old speeds beside the new ones: the
// worst region takes every pass joined to it on the surface, one beside the next, and no pass of
// a raster elsewhere (passes further apart than the gap limit are not joined).
TEST(regionOptimisation, TheWorstRegionTakesEveryPassJoinedToItAndNoOther) {
  std::string text = "G21 G90 G17 G94\n";
  int n = 1;
  std::vector<double> near, far;
  for (int p = 0; p < 61; ++p) near.push_back(0.5 * p);
  for (int p = 0; p < 16; ++p) far.push_back(40.0 + 0.5 * p);
  // The first raster's fillet only on passes 20 to 30: its defects lie there.
  rasterAt(near, [](double y) { return y >= 10 && y <= 15; }, text, n);
  const int firstOfFar = n;
  rasterAt(far, [](double) { return true; }, text, n);
  text += fmt::format("N{} G0 Z30.\nN{} M30\n", n, n + 1);
  const InterpretResult read = interpretGcode(text, "two-rasters.nc");
  ASSERT_TRUE(read.ok()) << read.errors.front().str();
  const SurfaceRun before =
      surfaceRun(std::make_shared<const Trajectory>(simulateRun(read.program, machineWithoutChordSmoothing())), &read.program);
  const ChosenRegion worst = worstRegion(before, "two-rasters.nc");
  // Its box is the defect's, a part of the first raster's passes.
  const bool inFar = worst.lower.y() >= 39;
  ASSERT_FALSE(inFar);
  EXPECT_LT(worst.upper.y() - worst.lower.y(), 20.0);
  // Its lines are every pass of that raster: from the plunge's pass to the last of its 61.
  std::uint32_t first = ~0u, last = 0;
  for (const Move& m : read.program.moves)
    if (m.kind == MoveKind::Linear && (m.end.y() >= 39) == inFar && m.end.z() < 29)
      first = std::min(first, m.line), last = std::max(last, m.line);
  EXPECT_LE(worst.lines.first, first + 2) << "from line " << first;
  EXPECT_GE(worst.lines.last, last - 1) << "to line " << last;
  // And no feed move of the other raster.
  for (const Move& m : read.program.moves)
    if (m.kind == MoveKind::Linear && (m.end.y() >= 39) != inFar) {
      EXPECT_FALSE(m.line >= worst.lines.first && m.line <= worst.lines.last) << "line " << m.line;
    }
  EXPECT_GT(firstOfFar, 100);
}
