// Region re-optimisation: the new program keeps every other line byte for byte, names what it
// replaced and stays on the old path. (The command and its comparison report are tested in
// tests/cli/region_optimizer_cli_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include <fmt/format.h>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/optimise/polyline_distance.h"
#include "isurface/optimise/region_optimizer.h"
#include "cam_style_transition.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// How far the new program's moves of a re-fitted pass lie from the old program's moves it
// replaced, both from the point the pass starts at (infinite when the new pass has no moves).
double passMovedBy(const Program& old, const Program& reread, const OptimizedPass& pass) {
  auto collect = [](const Program& p, std::uint32_t first, std::uint32_t last) {
    std::vector<Vec3> out;
    for (std::size_t i = 0; i < p.moves.size(); ++i) {
      if (p.moves[i].line < first || p.moves[i].line > last) continue;
      if (out.empty()) out.push_back(p.startOf(i));
      out.push_back(p.moves[i].end);
    }
    return out;
  };
  const std::vector<Vec3> newPath = collect(reread, pass.newFirstLine, pass.newLastLine);
  if (newPath.empty()) return INFINITY;
  return polylineDistance(newPath, collect(old, pass.firstLine, pass.lastLine));
}

}  // namespace

TEST(regionOptimizer, OnePassIsReplacedAndEverythingElseKept) {
  const std::string path = sourcePath("samples/transition-surface.nc");
  const std::string text = readFile(path);
  const InterpretResult original = interpretGcode(text, path);
  ASSERT_TRUE(original.ok());
  const OptimizeResult r = optimizeRegion(text, original.program, LineRange{70, 126}, defaultMachine());
  ASSERT_EQ(r.passes.size(), 1u);
  const OptimizedPass& pass = r.passes.front();
  EXPECT_EQ(pass.firstLine, 70u);
  EXPECT_GE(pass.lastLine, 120u);
  const std::vector<std::string> before = linesOf(text), after = linesOf(r.text);
  // Lines before the pass are the same lines.
  for (std::uint32_t i = 0; i + 1 < pass.firstLine; ++i) ASSERT_EQ(before[i], after[i]) << "line " << i + 1;
  // The block says which lines it replaces.
  EXPECT_NE(after[pass.firstLine - 1].find("lines 70-" + std::to_string(pass.lastLine)), std::string::npos)
      << after[pass.firstLine - 1];
  // Lines after the pass are the same lines, shifted.
  const std::size_t shift = after.size() - before.size();
  for (std::size_t i = pass.lastLine; i < before.size(); ++i) ASSERT_EQ(before[i], after[i + shift]) << "line " << i + 1;
  // The new program interprets, and its moves stay within 0.01 mm of the old path.
  const InterpretResult reread = interpretGcode(r.text, "new.nc");
  ASSERT_TRUE(reread.ok()) << reread.errors.front().str();
  EXPECT_LT(passMovedBy(original.program, reread.program, pass), 0.01);
}

TEST(regionOptimizer, NewBlocksAreWrittenInTheProgramsOwnFrame) {
  // Under a G92 or G52 offset or a G68 rotation the moves are where the frame puts them; the new
  // blocks are written in the program's coordinates, so the new program runs the same path.
  const std::string path = sourcePath("samples/transition-surface.nc");
  const std::string text = readFile(path);
  const std::size_t afterModes = text.find("T1 M6");
  for (const std::string frame : {"G92 X-409.5 Y20 Z-5", "G52 X100 Y-50 Z2", "G68 X20 Y10 R30"}) {
    // The frame line goes before line 5: the pass of lines 70-126 is now lines 71-127.
    const std::string framed = text.substr(0, afterModes) + frame + "\n" + text.substr(afterModes);
    const InterpretResult original = interpretGcode(framed, path);
    ASSERT_TRUE(original.ok()) << frame;
    const OptimizeResult r = optimizeRegion(framed, original.program, LineRange{71, 127}, defaultMachine());
    ASSERT_EQ(r.passes.size(), 1u) << frame;
    const OptimizedPass& pass = r.passes.front();
    const InterpretResult reread = interpretGcode(r.text, "new.nc");
    ASSERT_TRUE(reread.ok()) << reread.errors.front().str();
    EXPECT_LT(passMovedBy(original.program, reread.program, pass), 0.01) << frame;
    // And the lines after the pass go on from where the pass ends, as before.
    EXPECT_LT((reread.program.moves.back().end - original.program.moves.back().end).norm(), 1e-9) << frame;
  }
}

TEST(regionOptimizer, RefusesWhatItCannotRewrite) {
  const std::string incremental = "G21 G91\nG1 X1 F100\nG1 X1\nG1 X1\nG1 X1\nG1 X1\n";
  const InterpretResult r = interpretGcode(incremental, "inc.nc");
  EXPECT_THROW(optimizeRegion(incremental, r.program, LineRange{1, 6}, defaultMachine()), InputError);
  const std::string rapids = "G21 G90\nG0 X1\nG0 X2\nG0 X3\nG0 X4\nG0 X5\n";
  const InterpretResult q = interpretGcode(rapids, "rapid.nc");
  EXPECT_THROW(optimizeRegion(rapids, q.program, LineRange{1, 6}, defaultMachine()), InputError);
}

// A long straight move met by short ones along a curve: fitting across the jump in spacing
// would swing the spline off the path; the new points stay on it and the curve is cut finely.
TEST(regionOptimizer, JumpInSpacingDoesNotSwingTheFit) {
  std::string text = "G21 G90 G17\nG0 X0 Y0 Z0\nG1 X20 F3000\n";
  for (int k = 1; k <= 40; ++k) {
    const double a = k * 0.02;  // radians along a 20 mm radius arc leaving the line tangentially
    char block[64];
    std::snprintf(block, sizeof block, "G1 X%.4f Z%.4f\n", 20 + 20 * std::sin(a), 20 - 20 * std::cos(a));
    text += block;
  }
  const InterpretResult original = interpretGcode(text, "jump.nc");
  ASSERT_TRUE(original.ok());
  const OptimizeResult r = optimizeRegion(text, original.program, LineRange{3, 43}, defaultMachine());
  const InterpretResult reread = interpretGcode(r.text, "new.nc");
  ASSERT_TRUE(reread.ok()) << reread.errors.front().str();
  std::vector<Vec3> oldPath = {Vec3::Zero()}, newPath = {Vec3::Zero()};
  for (const Move& m : original.program.moves) oldPath.push_back(m.end);
  for (const Move& m : reread.program.moves) newPath.push_back(m.end);
  EXPECT_LT(polylineDistance(newPath, oldPath), 0.008);
  // The 0.4 mm chords of the arc turn the path 0.02 rad each; the new ones at most 0.01.
  ASSERT_EQ(r.passes.size(), 1u);
  EXPECT_GE(r.passes.front().newMoves, 2 * r.passes.front().oldMoves - 2);
  EXPECT_EQ(r.newRange.first, 3u);
  EXPECT_EQ(r.newRange.last, linesOf(r.text).size());
}

namespace {

// The program with every coordinate and feed word rewritten in inches and G21 made G20.
std::string inInches(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    const bool word = (c == 'X' || c == 'Y' || c == 'Z' || c == 'F' || c == 'I' || c == 'J') && i + 1 < text.size() &&
                      (std::isdigit(static_cast<unsigned char>(text[i + 1])) || text[i + 1] == '-' || text[i + 1] == '.');
    if (!word) {
      out += c;
      ++i;
      continue;
    }
    std::size_t used = 0;
    const double value = std::stod(text.substr(i + 1), &used);
    char number[32];
    std::snprintf(number, sizeof number, c == 'F' ? "%.3f" : "%.6f", value / 25.4);
    out += c;
    out += number;
    i += 1 + used;
  }
  const std::size_t g21 = out.find("G21");
  if (g21 != std::string::npos) out.replace(g21, 3, "G20");
  else out = "G20\n" + out;
  return out;
}

}  // namespace

TEST(regionOptimizer, AnInchProgramIsRewrittenInInches) {
  const std::string text = inInches(readFile(sourcePath("samples/transition-surface.nc")));
  const InterpretResult original = interpretGcode(text, "inch.nc");
  ASSERT_TRUE(original.ok()) << original.errors.front().str();
  const OptimizeResult r = optimizeRegion(text, original.program, LineRange{70, 126}, defaultMachine());
  ASSERT_EQ(r.passes.size(), 1u);
  const InterpretResult reread = interpretGcode(r.text, "inch-new.nc");
  ASSERT_TRUE(reread.ok()) << reread.errors.front().str();
  // Read back in inches, the new moves lie on the old path (mm inside) and keep its feed.
  const OptimizedPass& pass = r.passes.front();
  double farthest = 0;
  for (const Move& m : reread.program.moves) {
    if (m.line < pass.newFirstLine || m.line > pass.newLastLine) continue;
    double nearest = INFINITY;
    for (std::size_t i = 0; i < original.program.moves.size(); ++i)
      if (original.program.moves[i].line >= pass.firstLine && original.program.moves[i].line <= pass.lastLine)
        nearest = std::min(nearest, distanceToSegment(m.end, original.program.startOf(i), original.program.moves[i].end));
    farthest = std::max(farthest, nearest);
    // mm/min inside: the sample's F3000 written as in/min and read back, never above it.
    EXPECT_GE(m.feed, 0.2 * 3000 - 1);
    EXPECT_LE(m.feed, 3000 + 1);
  }
  EXPECT_LT(farthest, 0.01);  // mm
  EXPECT_THROW(optimizeRegion("G21\n" + text, original.program, LineRange{70, 126}, defaultMachine()), InputError);
}

namespace {

// Four raster passes along X whose points step up and down by 30 um, joined by step-overs in Y,
// entered by a plunge: in mm, or in inches.
std::string steppedRaster(bool inch) {
  const double unit = inch ? 25.4 : 1.0;
  std::string text = inch ? "G20 G90\nG0 X0 Y0 Z0.2\nG1 Z0 F40\n" : "G21 G90\nG0 X0 Y0 Z5\nG1 Z0 F1000\n";
  for (int pass = 0; pass < 4; ++pass) {
    for (int i = 1; i <= 40; ++i) {
      const int k = pass % 2 ? 40 - i : i;
      text += fmt::format("G1 X{:.5f} Y{:.5f} Z{:.5f}\n", 0.15 * k / unit, 0.5 * pass / unit, (k % 2 ? 0.03 : 0.0) / unit);
    }
    if (pass < 3) text += fmt::format("G1 Y{:.5f}\n", 0.5 * (pass + 1) / unit);
  }
  return text + "M2\n";
}

// The stepped raster's path drawn anew in `shape` at the program's feed, capped at `feedCap`.
struct SteppedRun {
  InterpretResult original;
  OptimizeOptions options;
  OptimizeResult result;
};
SteppedRun drawnAnew(bool inch, PathShape shape, double feedCap = 0) {
  SteppedRun run;
  run.original = interpretGcode(steppedRaster(inch), "stepped.nc");
  run.options.shape = shape;
  run.options.programmedFeed = true;
  run.options.feedCap = feedCap;
  run.result = optimizeRegion(steppedRaster(inch), run.original.program, LineRange{1, 200}, defaultMachine(), run.options);
  return run;
}

}  // namespace

TEST(regionOptimizer, PointsDrawnTautStayInTheirPassesAndTube) {
  for (const bool inch : {false, true}) {
    const SteppedRun run = drawnAnew(inch, PathShape::DrawnTaut, 700.4);  // mm/min
    const InterpretResult& original = run.original;
    ASSERT_TRUE(original.ok()) << original.errors.front().str();
    const OptimizeResult& r = run.result;
    // A pass ends at a step-over (a corner seen from above), however its points step in Z; the
    // plunge joins no pass.
    EXPECT_EQ(r.passes.size(), 4u) << r.text;
    const InterpretResult reread = interpretGcode(r.text, "stepped-new.nc");
    ASSERT_TRUE(reread.ok()) << reread.errors.front().str();
    std::vector<Vec3> before, after;
    for (std::size_t i = 0; i < original.program.moves.size(); ++i) before.push_back(original.program.moves[i].end);
    for (std::size_t i = 0; i < reread.program.moves.size(); ++i) after.push_back(reread.program.moves[i].end);
    EXPECT_LE(polylineDistance(before, after), 0.008 + 0.0003) << (inch ? "inch" : "mm");
    EXPECT_GT(polylineDistance(before, after), 0.007);  // the steps were lowered
    // The cap in the program's units (700 mm/min is 27.56 in/min), named once per pass, and the
    // old feed after each pass.
    EXPECT_NE(r.text.find(inch ? "drawn taut within 0.008 mm, feed F27.56)" : "drawn taut within 0.008 mm, feed F700)"),
              std::string::npos) << r.text;
    EXPECT_NE(r.text.find(inch ? "F27.56" : "F700"), std::string::npos) << r.text;
    EXPECT_NE(r.text.find(inch ? "\nF40.00\n" : "\nF1000\n"), std::string::npos) << r.text;
  }
}

TEST(regionOptimizer, RoundedCornersNameTheLineTheyStandFor) {
  for (const bool inch : {false, true}) {
    const SteppedRun run = drawnAnew(inch, PathShape::CornersRounded);
    const InterpretResult& original = run.original;
    ASSERT_TRUE(original.ok()) << original.errors.front().str();
    const OptimizeOptions& options = run.options;
    const OptimizeResult& r = run.result;
    EXPECT_EQ(r.passes.size(), 4u) << r.text;
    EXPECT_NE(r.text.find("re-fitted: corners rounded within 0.008 mm, feed F"), std::string::npos) << r.text;
    const InterpretResult reread = interpretGcode(r.text, "stepped-new.nc");
    ASSERT_TRUE(reread.ok()) << reread.errors.front().str();
    // Each new move's end lies on (within the tube of) the old line it names.
    const double tube = options.maximumDeviation + (inch ? 0.0003 : 0.0001);  // mm, and the last decimal
    for (const OptimizedPass& pass : r.passes) {
      ASSERT_EQ(pass.sourceLines.size(), pass.newMoves);
      EXPECT_GT(pass.newMoves, pass.oldMoves);  // the corners' arcs
      for (std::size_t k = 0; k < pass.newMoves; ++k) {
        const std::uint32_t newLine = pass.newFirstLine + 1 + static_cast<std::uint32_t>(k);
        const auto newMove = std::find_if(reread.program.moves.begin(), reread.program.moves.end(),
                                          [&](const Move& m) { return m.line == newLine; });
        const auto oldMove = std::find_if(original.program.moves.begin(), original.program.moves.end(),
                                          [&](const Move& m) { return m.line == pass.sourceLines[k]; });
        ASSERT_NE(newMove, reread.program.moves.end()) << newLine;
        ASSERT_NE(oldMove, original.program.moves.end()) << pass.sourceLines[k];
        const Vec3 a = original.program.startOf(static_cast<std::size_t>(oldMove - original.program.moves.begin()));
        const Vec3 leg = oldMove->end - a;
        const double along = std::clamp((newMove->end - a).dot(leg) / leg.squaredNorm(), 0.0, 1.0);
        EXPECT_LE((newMove->end - (a + along * leg)).norm(), tube)
            << (inch ? "inch" : "mm") << " new line " << newLine << " names old line " << pass.sourceLines[k];
      }
    }
  }
}

namespace {

// The feed (mm/min) the new program runs at over x (mm) on the pass at y.
double newFeedAt(const Program& program, double y, double x) {
  for (std::size_t i = 0; i < program.moves.size(); ++i) {
    const Vec3 from = program.startOf(i), to = program.moves[i].end;
    if (std::fabs(from.y() - y) > 1e-6 || std::fabs(to.y() - y) > 1e-6) continue;
    if (x >= std::min(from.x(), to.x()) && x <= std::max(from.x(), to.x())) return program.moves[i].feed;
  }
  return NAN;
}

// Two passes of a zig-zag, the first along +X at Y0 over `there` (x, z), the second back at
// Y0.5 over `back`, at F2500; their bends eased (within 60 mm/s^2, ramps of 250 mm/s^2) and
// the new program read again.
Program easedZigzag(const std::vector<std::pair<double, double>>& there, const std::vector<std::pair<double, double>>& back) {
  std::string text = "G21 G90 G17\nG0 Z5\nG0 X0 Y0\nG1 Z0 F500\n";
  for (std::size_t k = 1; k < there.size(); ++k)
    text += fmt::format("G1 X{:.4f} Z{:.4f}{}\n", there[k].first, there[k].second, k == 1 ? " F2500" : "");
  text += "G1 Y0.5\n";
  for (std::size_t k = back.size() - 1; k-- > 0;) text += fmt::format("G1 X{:.4f} Z{:.4f}\n", back[k].first, back[k].second);
  const auto last = static_cast<std::uint32_t>(4 + there.size() - 1 + 1 + back.size() - 1);
  text += "G0 Z5\nM30\n";
  const InterpretResult original = interpretGcode(text, "zigzag.nc");
  EXPECT_TRUE(original.ok()) << original.errors.front().str();
  OptimizeOptions options;
  options.shape = PathShape::Eased;
  options.programmedFeed = true;
  options.normalAccelerationLimit = 60;  // mm/s^2: sqrt(60 * 5) = 1039 mm/min in a fillet of 5 mm
  options.rampAcceleration = 250;
  const OptimizeResult r = optimizeRegion(text, original.program, LineRange{5, last}, defaultMachine(), options);
  EXPECT_EQ(r.passes.size(), 2u) << r.text;
  const InterpretResult reread = interpretGcode(r.text, "zigzag-new.nc");
  EXPECT_TRUE(reread.ok()) << reread.errors.front().str();
  return reread.program;
}

}  // namespace

// Two passes of a zig-zag over the same profile (plane, fillet by a chord tolerance, slope),
// one each way: eased, they slow down and speed up at the same places, so that neither runs its
// bend's ramps ahead of the other's.
TEST(regionOptimizer, EasedPassesCutEachWaySlowAtTheSamePlaces) {
  isurface::testing::CamStyleTransition part;
  part.chordTolerance = 0.02;  // mm: three chords in the fillet
  const auto profile = isurface::testing::camProfile(part, 0.0);
  const Program eased = easedZigzag(profile, profile);
  double slowest = INFINITY;
  for (double x = 15; x < 30; x += 0.01) {
    const double there = newFeedAt(eased, 0.0, x);
    slowest = std::min(slowest, there);
    // A step of the ramps (25 mm/min) at most, where x falls on a piece's end; the pieces' ends
    // were placed on the program's grid up to a quarter of a piece (of at most 0.1 mm) away,
    // each pass's its own way.
    double nearest = INFINITY;
    for (const double dx : {-0.05, -0.0375, -0.025, -0.0125, 0.0, 0.0125, 0.025, 0.0375, 0.05}) nearest = std::min(nearest, std::fabs(there - newFeedAt(eased, 0.5, x + dx)));
    EXPECT_LE(nearest, 25.0 + 1e-9) << "x " << x;
  }
  EXPECT_LT(slowest, 1100);  // the bend is slowed
}

// Two neighbouring passes over the same fillet, one written in two chords and one in three (a
// CAM system's chord tolerance met by fewer chords as the radius grows): eased, the corners of
// the two-chord pass stay sharper and would run slower; the other pass is held to its speed.
TEST(regionOptimizer, EasedNeighboursWrittenInDifferentChordsRunTheirBendAlike) {
  isurface::testing::CamStyleTransition coarse, fine;
  coarse.chordTolerance = 0.03;  // mm: two chords in the fillet
  fine.chordTolerance = 0.015;   // three
  const auto there = isurface::testing::camProfile(coarse, 0.0), back = isurface::testing::camProfile(fine, 0.0);
  ASSERT_EQ(there.size() + 1, back.size());
  const Program eased = easedZigzag(there, back);
  double worst = 0, slowest = INFINITY;
  for (double x = 15; x < 30; x += 0.01) {
    // The nearest feed of the other pass within a piece's length (its pieces end elsewhere).
    const double a = newFeedAt(eased, 0.0, x);
    double nearest = INFINITY;
    for (double dx = -0.05; dx <= 0.05 + 1e-9; dx += 0.01) nearest = std::min(nearest, std::fabs(a - newFeedAt(eased, 0.5, x + dx)));
    worst = std::max(worst, nearest);
    slowest = std::min(slowest, a);
  }
  // 1.5 % of F between the passes' points, a step of the ramps (1 % of F) where a point's speed
  // is the slower of its two moves', and a step for rounding (each pass on its own: 250).
  EXPECT_LE(worst, 0.035 * 2500 + 1e-9);
  EXPECT_LT(slowest, 1200);
}

// A pass over two bends (a fillet from the plane onto a slope, a round from the slope onto a
// plateau), re-planned in a box over the first: the first is re-fitted from the plane's move to
// the slope's, the second's lines are kept byte for byte.
TEST(regionOptimizer, OnlyTheStretchOfAPassAcrossTheBoxIsReplanned) {
  isurface::testing::CamStyleTransition part;
  part.length = 35;  // mm: the slope ends there
  auto profile = isurface::testing::camProfile(part, 0.0);
  const double theta = part.slopeDegrees * M_PI / 180, r = 6;  // the round, mm
  const auto [xs, zs] = profile.back();
  // Its centre below the path, the direction turning from the slope's to level.
  const Vec3 centre(xs + r * std::sin(theta), 0, zs - r * std::cos(theta));
  for (int k = 1; k <= 12; ++k) {
    const double phi = -theta * (1 - k / 12.0);
    profile.emplace_back(centre.x() + r * std::sin(phi), centre.z() + r * std::cos(phi));
  }
  profile.emplace_back(70.0, profile.back().second);
  std::string text = "G21 G90 G17\nG0 Z30\nG0 X0 Y0\nG1 Z0 F800\n";
  for (std::size_t k = 1; k < profile.size(); ++k)
    text += fmt::format("G1 X{:.4f} Z{:.4f}{}\n", profile[k].first, profile[k].second, k == 1 ? " F2500" : "");
  const auto last = static_cast<std::uint32_t>(4 + profile.size() - 1);
  text += "G0 Z30\nM30\n";
  const InterpretResult original = interpretGcode(text, "two-bends.nc");
  ASSERT_TRUE(original.ok()) << original.errors.front().str();
  OptimizeOptions options;
  options.planBox = std::make_pair(Vec3(20, -1, -100), Vec3(24, 1, 100));  // over the fillet
  const OptimizeResult result = optimizeRegion(text, original.program, LineRange{5, last}, defaultMachine(), options);
  ASSERT_EQ(result.passes.size(), 1u) << result.text;
  const OptimizedPass& pass = result.passes.front();
  // From the plane's move (line 5) to the slope's, which reaches 35 mm: the round's chords after it stay.
  EXPECT_EQ(pass.firstLine, 5u);
  const std::vector<std::string> before = linesOf(text), after = linesOf(result.text);
  const auto slope = std::find_if(before.begin(), before.end(), [&](const std::string& l) { return l.find(fmt::format("X{:.4f}", xs)) != std::string::npos; });
  ASSERT_NE(slope, before.end());
  EXPECT_EQ(pass.lastLine, std::uint32_t(slope - before.begin()) + 1);
  for (std::size_t i = pass.lastLine; i < before.size(); ++i)
    EXPECT_NE(std::find(after.begin(), after.end(), before[i]), after.end()) << "line " << i + 1 << ": " << before[i];
  // Without the box, the whole pass is re-planned.
  options.planBox.reset();
  const OptimizeResult whole = optimizeRegion(text, original.program, LineRange{5, last}, defaultMachine(), options);
  ASSERT_EQ(whole.passes.size(), 1u);
  EXPECT_EQ(whole.passes.front().lastLine, last);
}
