// Splitting samples into cutting passes: synthetic rasters, loops, spirals and free paths, the
// bundled sample parts and a real raster program.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "surface_fixtures.h"
#include "isurface/surface/passes.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

double chordXY(const Trajectory& s, const Pass& p) {
  return std::hypot(s.x[p.end - 1] - s.x[p.begin], s.y[p.end - 1] - s.y[p.begin]);
}

TEST(passes, PatternNames) {
  EXPECT_STREQ(pathPatternName(PathPattern::DirectionParallel), "direction-parallel");
  EXPECT_STREQ(pathPatternName(PathPattern::ContourParallel), "contour-parallel");
  EXPECT_STREQ(pathPatternName(PathPattern::NoBoundary), "no-boundary");
  EXPECT_STREQ(pathPatternName(PathPattern::Auto), "auto");
}

TEST(passes, EmptyTrajectoryHasNoPasses) {
  const PassSet set = splitPasses(Trajectory{});
  EXPECT_TRUE(set.passes.empty());
}

TEST(passes, ZigZagRasterOnePassPerLine) {
  const Trajectory s = zigZagRaster(12, 40.0, 0.5, 3000);
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  ASSERT_EQ(set.passes.size(), 12u);
  for (std::size_t k = 0; k < set.passes.size(); ++k) {
    const Pass& p = set.passes[k];
    // Along X, alternating, on its own line of Y; the step-overs are left out.
    EXPECT_NEAR(chordXY(s, p), 40.0, 0.2) << k;
    const double dx = s.x[p.end - 1] - s.x[p.begin];
    EXPECT_EQ(dx > 0, k % 2 == 0) << k;
    for (std::size_t i = p.begin; i < p.end; ++i) ASSERT_NEAR(s.y[i], 0.5 * double(k), 1e-9) << k;
    if (k > 0) {
      EXPECT_GE(p.begin, set.passes[k - 1].end);
    }
  }
}

// A zig-zag of `passes` passes `length` mm long, 0.6 mm apart, along a direction 30 degrees off X.
Trajectory rasterAtThirtyDegrees(int passes, double length, double feed) {
  const double c = std::cos(kPi / 6), s30 = std::sin(kPi / 6);
  const auto at = [&](double u, double v) { return Vec3(u * c - v * s30, u * s30 + v * c, 0); };
  PathSampler path(at(0, 0));
  for (int k = 0; k < passes; ++k) {
    if (k > 0) path.lineTo(at(k % 2 == 0 ? 0 : length, 0.6 * k), feed);
    path.lineTo(at(k % 2 == 0 ? length : 0, 0.6 * k), feed);
  }
  return path.take();
}

TEST(passes, RasterAtAnAngleFindsItsAxis) {
  const Trajectory s = rasterAtThirtyDegrees(8, 30, 2000);
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  EXPECT_EQ(set.passes.size(), 8u);
}

TEST(passes, ALongRasterAtAnAngleFindsItsAxis) {
  // Over a million samples: the steps are summed in two halves (on two threads where it can).
  const Trajectory s = rasterAtThirtyDegrees(61, 300, 1000);
  ASSERT_GT(s.size(), 1'000'000u);
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  ASSERT_EQ(set.passes.size(), 61u);
  for (const Pass& p : set.passes) EXPECT_NEAR(chordXY(s, p), 300.0, 0.5);
}

// One-way raster: cut along +X, retract, rapid back, plunge.
Trajectory oneWayRaster(int passes, bool withFeed) {
  PathSampler path(Vec3(0, 0, 0));
  if (withFeed) path.withFeed();
  for (int k = 0; k < passes; ++k) {
    const double y = 0.8 * k;
    path.lineTo(Vec3(30, y, 0), 2000);
    path.lineTo(Vec3(30, y, 5), 1000);                 // retract at feed
    path.lineTo(Vec3(0, y + 0.8, 5), 20000, 20000);   // rapid return
    path.lineTo(Vec3(0, y + 0.8, 0), 1000);            // plunge
  }
  return path.take();
}

TEST(passes, OneWayRasterWithFeedChannel) {
  Trajectory s = oneWayRaster(6, true);
  s.rapidFeed = 20000;
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  ASSERT_EQ(set.passes.size(), 6u);
  for (const Pass& p : set.passes) {
    EXPECT_GT(s.x[p.end - 1], s.x[p.begin] + 29);  // all the same way
    // Never the links (but for the plunge's last sample, within one sample spacing).
    for (std::size_t i = p.begin; i < p.end; ++i) ASSERT_NEAR(s.z[i], 0, 0.017);
  }
}

// Cuts along +X and rapids back along -X at the cutting height to the next pass, the rapids at
// `rapid` mm/min (the machine's rate) and logged in the feed channel as `logged`; every pass found
// must be a cut, never a rapid back.
void expectOnlyTheCutsArePasses(double rapid, double logged) {
  PathSampler path(Vec3(0, 0, 0));
  path.withFeed();
  for (int k = 0; k < 6; ++k) {
    path.lineTo(Vec3(30, 0.8 * k, 0), 2000, 2000);
    path.lineTo(Vec3(0, 0.8 * (k + 1), 0), rapid, logged);
  }
  Trajectory s = path.take();
  s.rapidFeed = rapid;
  const PassSet set = splitPasses(s);
  ASSERT_EQ(set.passes.size(), 6u);
  for (const Pass& p : set.passes) EXPECT_GT(s.x[p.end - 1], s.x[p.begin] + 29);
}

// The feed channel holds floats: a rapid rate a float cannot hold is still told apart.
TEST(passes, ARapidRateThatIsNotAFloatIsStillARapid) { expectOnlyTheCutsArePasses(12345.678, 12345.678); }

// A program whose feed lies above the machine's rapid rate (a placeholder F, the machine going
// as fast as it can): its cutting moves are not rapids.
TEST(passes, AFeedAboveTheRapidRateIsCutting) {
  PathSampler path(Vec3(0, 0, 0));
  path.withFeed();
  const double rapid = 24000, programmed = 25374.6;  // mm/min: F999 in/min
  for (int k = 0; k < 6; ++k) {
    path.lineTo(Vec3(30, 0.8 * k, 0), 2000, programmed);  // the machine's limits hold it at 2000
    path.lineTo(Vec3(30, 0.8 * k, 5), 1000, programmed);
    path.lineTo(Vec3(0, 0.8 * (k + 1), 5), rapid, rapid);
    path.lineTo(Vec3(0, 0.8 * (k + 1), 0), 1000, programmed);
  }
  Trajectory s = path.take();
  s.rapidFeed = rapid;
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  ASSERT_EQ(set.passes.size(), 6u);
  for (const Pass& p : set.passes) EXPECT_GT(s.x[p.end - 1], s.x[p.begin] + 29);  // never the rapid back
}

// A short climb between two passes looks like a retract, and a later drop like a plunge; the
// passes between them go on below where the climb started, so they are cut, not air moves.
TEST(passes, AClimbFollowedByCuttingBelowItIsNotARetract) {
  PathSampler path(Vec3(0, 0, 0));
  path.lineTo(Vec3(30, 0, 0), 2000);
  path.lineTo(Vec3(30, 0, 0.3), 1000);      // the climb: vertical, turning from +X to +Y
  path.lineTo(Vec3(30, 0.8, 0.3), 2000);
  path.lineTo(Vec3(0, 0.8, -1), 2000);      // down a slope, below where the climb started
  path.lineTo(Vec3(0, 1.6, -1), 2000);
  path.lineTo(Vec3(30, 1.6, -1), 2000);
  path.lineTo(Vec3(30, 2.4, -1), 2000);
  path.lineTo(Vec3(0, 2.4, -1), 2000);
  path.lineTo(Vec3(0, 2.4, -3), 1000);      // the drop: vertical, turning from -X to +X
  path.lineTo(Vec3(30, 2.4, -3), 2000);
  const Trajectory s = path.take();
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  EXPECT_EQ(set.passes.size(), 5u);
}

// A real air move: retract, a link that comes part of the way down, a plunge. It is not cut.
TEST(passes, ALinkComingPartOfTheWayDownBeforeItsPlungeIsAnAirMove) {
  PathSampler path(Vec3(0, 0, 0));
  path.lineTo(Vec3(40, 0, 0), 2000);
  path.lineTo(Vec3(40, 0, 5), 1000);  // retract
  path.lineTo(Vec3(0, 1, 1), 2000);   // back, coming down to 1 mm above the part
  path.lineTo(Vec3(0, 1, 0), 1000);   // plunge
  path.lineTo(Vec3(40, 1, 0), 2000);
  const Trajectory s = path.take();
  const PassSet set = splitPasses(s);
  ASSERT_EQ(set.passes.size(), 2u);
  for (const Pass& p : set.passes)
    for (std::size_t i = p.begin; i < p.end; ++i) ASSERT_NEAR(s.z[i], 0, 0.02) << i;
}

// Rapids logged a float step or two off the machine's rate are still rapids.
TEST(passes, ARapidRateAFloatStepOffIsStillARapid) {
  expectOnlyTheCutsArePasses(24000, std::nextafter(std::nextafter(24000.0f, 1e9f), 1e9f));
}

TEST(passes, OneWayRasterRapidRateGuessedFromFeeds) {
  const Trajectory s = oneWayRaster(6, true);  // rapidFeed unknown: 20000 is 10 times the cutting feed
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  EXPECT_EQ(set.passes.size(), 6u);
}

TEST(passes, OneWayRasterFromSpeedAlone) {
  const Trajectory s = oneWayRaster(6, false);
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  ASSERT_EQ(set.passes.size(), 6u);
  for (const Pass& p : set.passes) EXPECT_GT(s.x[p.end - 1], s.x[p.begin] + 29);
}

TEST(passes, ConcentricLoopsOnePassPerLoop) {
  const Trajectory s = concentricLoops(10, 20.0, 1.0, 3000);
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::ContourParallel);
  ASSERT_EQ(set.passes.size(), 10u);
  for (std::size_t k = 0; k < set.passes.size(); ++k) {
    const Pass& p = set.passes[k];
    const double r = 20.0 - double(k);
    // Closed: ends where it starts, and every sample on its circle (the radial link is left
    // out, but for the last sample, which may lie on the link within one sample spacing of
    // 0.05 mm).
    EXPECT_LT((s.commanded(p.end - 1) - s.commanded(p.begin)).norm(), 0.1) << k;
    for (std::size_t i = p.begin; i < p.end; ++i) ASSERT_NEAR(std::hypot(s.x[i], s.y[i]), r, 0.05) << k;
    EXPECT_NEAR(pathLengthOf(s, p), 2 * kPi * r, 0.2) << k;
  }
}

// A control rounds the corner from a loop into its link: the sample nearest the loop's start
// then lies in the rounding, heading half into the link. The next loop still starts where the
// link comes back to the loop's heading, on its circle, not a link's length or a loop's later.
TEST(passes, LoopsWhoseLinkCornerIsRoundedStartOnTheirCircle) {
  const double outer = 20.0, step = 1.0, rounding = 0.02;  // mm
  PathSampler path(Vec3(outer, 0, 0));
  for (int k = 0; k < 6; ++k) {
    const double r = outer - k * step;
    if (k > 0) path.lineTo(Vec3(r, 0, 0), 3000);
    path.arc(Vec3::Zero(), 2 * kPi - rounding / r, r, 0, 3000);
    if (k < 5) path.arc(Vec3(r - rounding, -rounding, 0), kPi / 2, rounding, 0, 300);  // slowly round the corner
  }
  const Trajectory s = path.take();
  const PassSet set = splitPasses(s);
  ASSERT_EQ(set.passes.size(), 6u);
  for (std::size_t k = 0; k < set.passes.size(); ++k) {
    const Pass& p = set.passes[k];
    const double r = outer - double(k) * step;
    EXPECT_NEAR(std::hypot(s.x[p.begin], s.y[p.begin]), r, 0.05) << k;
    EXPECT_NEAR(pathLengthOf(s, p), 2 * kPi * r, 0.2) << k;
  }
}

TEST(passes, SpiralOnePassPerRevolution) {
  // An Archimedean spiral of 6 turns from radius 20 to 8 (2 mm a turn).
  PathSampler path(Vec3(20, 0, 0));
  path.arc(Vec3::Zero(), 6 * 2 * kPi, 8.0, 0, 3000);
  const Trajectory s = path.take();
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::ContourParallel);
  ASSERT_EQ(set.passes.size(), 6u);
  for (const Pass& p : set.passes) {
    // One revolution: starts and ends near the +X axis, one pitch apart.
    EXPECT_NEAR(std::atan2(s.y[p.begin], s.x[p.begin]), 0.0, 0.05);
    EXPECT_NEAR((s.commanded(p.end - 1) - s.commanded(p.begin)).norm(), 2.0, 0.1);
  }
}

TEST(passes, ClockwiseLoopsWithStepDownLinks) {
  // Waterline levels: clockwise squares stacked in Z, joined by a vertical step down at the start.
  PathSampler path(Vec3(0, -10, 0));
  for (int level = 0; level < 5; ++level) {
    const double z = -0.5 * level;
    if (level > 0) path.lineTo(Vec3(0, -10, z), 500);
    path.lineTo(Vec3(-10, -10, z), 2000).lineTo(Vec3(-10, 10, z), 2000).lineTo(Vec3(10, 10, z), 2000);
    path.lineTo(Vec3(10, -10, z), 2000).lineTo(Vec3(0, -10, z), 2000);
  }
  const Trajectory s = path.take();
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::ContourParallel);
  ASSERT_EQ(set.passes.size(), 5u);
  for (std::size_t k = 0; k < set.passes.size(); ++k) {
    const Pass& p = set.passes[k];
    // The step down is left out.
    for (std::size_t i = p.begin; i < p.end; ++i) ASSERT_NEAR(s.z[i], -0.5 * double(k), 1e-9) << k;
    EXPECT_NEAR(pathLengthOf(s, p), 80.0, 0.2);
  }
}

TEST(passes, FreePathIsCutByDistance) {
  // A meander that neither reverses nor winds: no boundary, a pass every 50 mm.
  PathSampler path(Vec3(0, 0, 0));
  for (int i = 1; i <= 600; ++i) {
    const double x = 0.5 * i;
    path.lineTo(Vec3(x, 10 * std::sin(x / 10), 0.5 * std::sin(x / 7)), 3000);
  }
  const Trajectory s = path.take();
  const double total = pathLengthOf(s, {0, s.size()});
  // Whole pieces, and the rest as one more when it is not shorter than the minimum pass.
  const auto expected = [&](double every) {
    const double whole = std::floor(total / every);
    return static_cast<std::size_t>(whole) + (total - whole * every >= 2.0 ? 1 : 0);
  };
  PassOptions options;
  const PassSet set = splitPasses(s, options);
  EXPECT_EQ(set.pattern, PathPattern::NoBoundary);
  EXPECT_EQ(set.passes.size(), expected(50.0));
  for (std::size_t k = 0; k + 1 < set.passes.size(); ++k) EXPECT_NEAR(pathLengthOf(s, set.passes[k]), 50.0, 0.2);

  options.noBoundaryDistance = 20;
  EXPECT_EQ(splitPasses(s, options).passes.size(), expected(20.0));
}

TEST(passes, PatternCanBeForced) {
  const Trajectory s = zigZagRaster(6, 40.0, 0.5, 3000);
  PassOptions options;
  options.pattern = PathPattern::NoBoundary;
  options.noBoundaryDistance = 100;
  const PassSet set = splitPasses(s, options);
  EXPECT_EQ(set.pattern, PathPattern::NoBoundary);
  EXPECT_EQ(set.passes.size(), 3u);  // 242.5 mm of path: 100, 100 and 42.5
  options.pattern = PathPattern::ContourParallel;
  EXPECT_EQ(splitPasses(s, options).pattern, PathPattern::ContourParallel);
}

TEST(passes, ShortRunsAreLeftOut) {
  // Passes 1.5 mm long are shorter than the default minimum of 2 mm.
  const Trajectory s = zigZagRaster(6, 1.5, 0.5, 600);
  PassOptions options;
  options.pattern = PathPattern::DirectionParallel;
  EXPECT_TRUE(splitPasses(s, options).passes.empty());
  options.minimumPassLength = 1.0;
  EXPECT_EQ(splitPasses(s, options).passes.size(), 6u);
}

TEST(passes, NonFiniteSamplesDoNotSplitAPass) {
  Trajectory s = zigZagRaster(4, 40.0, 0.5, 3000);
  s.x[300] = std::numeric_limits<double>::quiet_NaN();
  s.z[1000] = std::numeric_limits<double>::infinity();
  const PassSet set = splitPasses(s);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  EXPECT_EQ(set.passes.size(), 4u);
}

// --- with the program --------------------------------------------------------------------------

TEST(passes, ProgramRapidsPlungesAndAirMovesDoNotCut) {
  const std::string gcode =
      "G21 G90 G17\n"
      "G0 Z10\n"
      "G0 X0 Y0\n"
      "G1 Z0 F500\n"           // plunge
      "G1 X40 F3000\n"         // pass 1
      "G1 Z2 F1000\n"          // retract at feed
      "G1 X0 Y1 F3000\n"       // air move back at clearance
      "G1 Z0 F500\n"           // plunge
      "G1 X40 F3000\n"         // pass 2
      "G0 Z10\n"
      "G0 X0 Y2\n"
      "G1 Z0 F500\n"
      "G1 X40 F3000\n"         // pass 3
      "G0 Z10\n";
  const Simulated sim = simulateGcode(gcode);
  PassOptions options;
  options.program = &sim.program;
  const PassSet set = splitPasses(sim.samples, options);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  ASSERT_EQ(set.passes.size(), 3u);
  const std::uint32_t lines[3] = {5, 9, 13};
  for (std::size_t k = 0; k < 3; ++k) {
    const Pass& p = set.passes[k];
    for (std::size_t i = p.begin; i < p.end; ++i) ASSERT_EQ(sim.samples.line[i], lines[k]) << k;
    EXPECT_GT(chordXY(sim.samples, p), 39.0);
  }
  // The same without the program: feeds, lines and geometry tell the same story.
  const PassSet alone = splitPasses(sim.samples);
  ASSERT_EQ(alone.passes.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(sim.samples.line[alone.passes[k].begin], lines[k]);
}

TEST(passes, SteepWallInsideAPassIsKept) {
  // A raster over a step 3 mm high: the vertical moves on the wall belong to the passes.
  std::ostringstream g;
  g << "G21 G90 G17\nG0 Z10\nG0 X0 Y0\nG1 Z0 F500\n";
  for (int k = 0; k < 4; ++k) {
    const double y = 0.5 * k;
    if (k > 0) g << "G1 Y" << y << " F3000\n";
    if (k % 2 == 0) {
      g << "G1 X20 F3000\nG1 Z3\nG1 X40\n";
    } else {
      g << "G1 X20 F3000\nG1 Z0\nG1 X0\n";
    }
  }
  g << "G0 Z10\n";
  const Simulated sim = simulateGcode(g.str());
  PassOptions options;
  options.program = &sim.program;
  const PassSet set = splitPasses(sim.samples, options);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  ASSERT_EQ(set.passes.size(), 4u);
  for (const Pass& p : set.passes) EXPECT_GT(chordXY(sim.samples, p), 39.0);
}

// --- the bundled parts and real programs -------------------------------------------------------

struct PartCase {
  const char* name;
  PathPattern pattern;
  std::size_t passes;
};

class SamplePartPasses : public ::testing::TestWithParam<PartCase> {};

TEST_P(SamplePartPasses, CountAndPattern) {
  const PartCase& c = GetParam();
  const std::string file = sourcePath(std::string("samples/") + c.name + ".nc");
  const Simulated sim = simulateGcode(readFile(file), file);
  PassOptions options;
  options.program = &sim.program;
  const PassSet set = splitPasses(sim.samples, options);
  EXPECT_EQ(set.pattern, c.pattern);
  EXPECT_EQ(set.passes.size(), c.passes);
  // Without the program too.
  const PassSet alone = splitPasses(sim.samples);
  EXPECT_EQ(alone.pattern, c.pattern);
  EXPECT_EQ(alone.passes.size(), c.passes);
  for (const Pass& p : set.passes) {
    // Cutting only: never up at the safe height of the links (25 mm).
    for (std::size_t i = p.begin; i < p.end; ++i) ASSERT_LT(sim.samples.z[i], 24.0);
  }
}

// As sample_parts.cpp makes them: transition-surface, 81 raster lines 0.5 mm apart;
// cola-bottle-bottom, loops from r = 44 to 0.5 in 0.5 mm steps (88); wuzhishan, r = 38 down to
// 1.2 in 0.8 mm steps (47).
INSTANTIATE_TEST_SUITE_P(parts, SamplePartPasses,
                         ::testing::Values(PartCase{"transition-surface", PathPattern::DirectionParallel, 81},
                                           PartCase{"cola-bottle-bottom", PathPattern::ContourParallel, 88},
                                           PartCase{"wuzhishan", PathPattern::ContourParallel, 47}),
                         [](const auto& info) {
                           std::string n = info.param.name;
                           for (char& ch : n)
                             if (ch == '-') ch = '_';
                           return n;
                         });

TEST(passes, CameoRasterPrefix) {
  const std::string path = realdataPath("cameo.nc");
  ISURFACE_SKIP_WITHOUT_REALDATA(path);
  // The first 600 lines: full-width raster lines along X with Y steps of 0.25 to 0.5 mm.
  std::ifstream in(path);
  std::string text, line;
  for (int i = 0; i < 600 && std::getline(in, line); ++i) text += line + "\n";
  const Simulated sim = simulateGcode(text, "cameo.nc");
  PassOptions options;
  options.program = &sim.program;
  const PassSet set = splitPasses(sim.samples, options);
  EXPECT_EQ(set.pattern, PathPattern::DirectionParallel);
  ASSERT_GE(set.passes.size(), 10u);
  const Trajectory& s = sim.samples;
  for (std::size_t k = 0; k < set.passes.size(); ++k) {
    const Pass& p = set.passes[k];
    // Each pass on one line of Y, alternating along X, the last one perhaps cut short.
    double lo = s.y[p.begin], hi = lo;
    for (std::size_t i = p.begin; i < p.end; ++i) lo = std::min(lo, s.y[i]), hi = std::max(hi, s.y[i]);
    EXPECT_LT(hi - lo, 0.02) << k;
    const double dx = s.x[p.end - 1] - s.x[p.begin];
    if (k + 1 < set.passes.size()) {
      EXPECT_GT(std::fabs(dx), 149.0) << k;
    }
    if (k > 0) {
      const double previous = s.x[set.passes[k - 1].end - 1] - s.x[set.passes[k - 1].begin];
      EXPECT_LT(dx * previous, 0) << k;
      const double stepOver = s.y[p.begin] - s.y[set.passes[k - 1].begin];
      EXPECT_GT(stepOver, 0.2) << k;
      EXPECT_LT(stepOver, 0.55) << k;
    }
  }
  const PassSet alone = splitPasses(s);
  EXPECT_EQ(alone.passes.size(), set.passes.size());
}

}  // namespace
