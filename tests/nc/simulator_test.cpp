// The NC interpolator model: feed planning, interpolation, filters and servo, checked from the
// outside (finite differences of written positions, distance to the programmed geometry).
#include <gtest/gtest.h>

#include <cmath>

#include "motion_checks.h"
#include "isurface/io/biip.h"
#include "isurface/base/units.h"
#include "isurface/nc/feed_plan.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/nc/servo_response.h"
#include "isurface/nc/simulator.h"
#include "isurface/workflow/simulation_dump.h"
#include "test_support.h"

using namespace isurface;
using isurface::test::MotionChecker;
using isurface::test::MotionExtremes;
using isurface::test::expectWithinLimits;

namespace {


Move line(const Vec3& end, double feed, std::uint32_t sourceLine) {
  Move m;
  m.kind = MoveKind::Linear;
  m.end = end;
  m.feed = static_cast<float>(feed);
  m.line = sourceLine;
  return m;
}

Program programOf(std::vector<Move> moves) {
  Program p;
  p.source = "test";
  p.moves = std::move(moves);
  return p;
}

Program parse(const std::string& text) {
  InterpretResult r = interpretGcode(text, "test.nc");
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front().str());
  return std::move(r.program);
}

int filterWindow(const Machine& m, const Program& p) {
  const FeedPlan plan = planFeed(p, m);
  return static_cast<int>((plan.filterTime1 + plan.filterTime2) / m.cycle) + 2;
}

MotionExtremes run(const Program& program, const Machine& machine, bool geometry = true) {
  MotionChecker checker(program, machine, filterWindow(machine, program), geometry);
  simulate(program, machine, checker);
  return checker.finish();
}

// A circle of radius r approximated by G1 moves of the given chord length.
Program polygonCircle(double radius, double chord, double feed) {
  std::vector<Move> moves;
  const int n = static_cast<int>(std::ceil(2 * kPi * radius / chord));
  for (int i = 1; i <= n; ++i) {
    const double a = 2 * kPi * i / n;
    moves.push_back(line(Vec3(radius * std::cos(a), radius * std::sin(a), 0), feed, i));
  }
  Program p = programOf(moves);
  p.start = Vec3(radius, 0, 0);
  return p;
}

}  // namespace

TEST(FeedPlan, ThreePointRadiusOfACircleAndDegenerateTriples) {
  const double r = 7.5;
  const Vec3 a(r, 0, 0), b(r * std::cos(0.3), r * std::sin(0.3), 0), c(r * std::cos(0.7), r * std::sin(0.7), 0);
  EXPECT_NEAR(threePointRadius(a, b, c), r, 1e-9);
  EXPECT_TRUE(std::isinf(threePointRadius(Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2))));
  EXPECT_TRUE(std::isinf(threePointRadius(Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(4, 5, 6))));
  EXPECT_TRUE(std::isinf(threePointRadius(Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3))));
}

TEST(Simulator, LongLineReachesFeedAndTakesTheTimeOfItsProfile) {
  const Machine m = defaultMachine();
  const Program p = programOf({line(Vec3(200, 0, 0), 3000, 1)});
  const MotionExtremes r = run(p, m);
  expectWithinLimits(r, m);
  EXPECT_NEAR(r.maxSpeed, 50.0, 0.05);  // F3000 = 50 mm/s
  // 200 mm at 50 mm/s, plus v/a for the two ramps at half the axis acceleration, plus the
  // filters' spread: they start moving before the profile does and settle after it.
  const FeedPlan plan = planFeed(p, m);
  const double a = 0.5 * m.axes[0].maxAcceleration;
  const double expected = 200.0 / 50.0 + 50.0 / a + plan.filterTime1 + plan.filterTime2 - 2 * m.cycle;
  EXPECT_NEAR(r.duration, expected, 0.003);
}

TEST(Simulator, ShortSegmentsFlowAtSpeedInsteadOfStoppingAtEachBlock) {
  const Machine m = defaultMachine();
  // 0.1 mm moves on a 200 mm radius: gentle curvature, F3000 must hold.
  const Program p = polygonCircle(200.0, 0.1, 3000);
  SampleBuffer buffer;
  simulate(p, m, buffer);
  const auto& s = buffer.data;
  ASSERT_GT(s.size(), 1000u);
  double slowest = 1e9;
  for (std::size_t i = s.size() / 4; i < 3 * s.size() / 4; ++i) {
    const double v = std::hypot(s[i].x - s[i - 1].x, s[i].y - s[i - 1].y) / m.cycle;
    slowest = std::min(slowest, v);
  }
  EXPECT_GT(slowest, 0.98 * 50.0);
  expectWithinLimits(run(p, m), m);
}

TEST(Simulator, TightPolygonSlowsDownForCurvatureAndStaysInTolerance) {
  const Machine m = defaultMachine();
  const MotionExtremes r = run(polygonCircle(3.0, 0.05, 3000), m);
  expectWithinLimits(r, m);
  EXPECT_LT(r.maxSpeed, 50.0 * 0.9);  // a 3 mm radius cannot be taken at F3000 within 10 um
  EXPECT_GT(r.maxSpeed, 5.0);
}

TEST(Simulator, SharpCornersAreRoundedWithinTheChordTolerance) {
  const Machine m = defaultMachine();
  const Program p = programOf({line(Vec3(20, 0, 0), 3000, 1), line(Vec3(20, 20, 0), 3000, 2),
                               line(Vec3(0, 20, -1), 3000, 3), line(Vec3(0, 0, 0), 3000, 4)});
  expectWithinLimits(run(p, m), m);
}

TEST(Simulator, ArcsInEveryPlaneAndHelixRespectLimitsAndGeometry) {
  const Machine m = defaultMachine();
  const Program p = parse(
      "G21 G90 G17 F3000\nG1 X10 Y0 Z0\nG3 X10 Y0 I-10 J0\nG2 X0 Y10 Z-2 R10\n"
      "G18 G1 X0 Y10 Z0\nG2 X10 Z0 I5 K0\nG19 G3 Y20 Z0 J5 K0\nG17 G2 X10 Y20 I0 J-2 P3\n");
  const MotionExtremes r = run(p, m);
  expectWithinLimits(r, m);
}

TEST(Simulator, ExactStopComesToRestAtTheCorner) {
  const Machine m = defaultMachine();
  Move first = line(Vec3(30, 0, 0), 3000, 1);
  first.flags = kExactStop;
  const Program p = programOf({first, line(Vec3(30, 30, 0), 3000, 2)});
  SampleBuffer buffer;
  simulate(p, m, buffer);
  double closest = 1e9;
  for (const SimSample& s : buffer.data) closest = std::min(closest, (Vec3(s.x, s.y, s.z) - Vec3(30, 0, 0)).norm());
  EXPECT_LT(closest, 1e-6);  // the corner itself is reached, not rounded
}

TEST(Simulator, DwellTimeCounts) {
  const Machine m = defaultMachine();
  const Program plain = parse("G1 X10 F1200\nG1 X20\n");
  const Program dwell = parse("G1 X10 F1200\nG4 P1.5\nG1 X20\n");
  SampleBuffer a, b;
  const SimulationReport ra = simulate(plain, m, a);
  const SimulationReport rb = simulate(dwell, m, b);
  // The dwell adds 1.5 s and forces a stop at X10 (a little more time).
  EXPECT_GT(rb.machiningTime - ra.machiningTime, 1.5);
  EXPECT_LT(rb.machiningTime - ra.machiningTime, 1.5 + 0.2);
}

TEST(Simulator, ZeroLengthAndDuplicateMovesDoNotStopOrBreak) {
  const Machine m = defaultMachine();
  const Program p = programOf({line(Vec3(10, 0, 0), 3000, 1), line(Vec3(10, 0, 0), 3000, 2),
                               line(Vec3(20, 0, 0), 3000, 3), line(Vec3(20, 0, 0), 3000, 4)});
  SampleBuffer buffer;
  const SimulationReport r = simulate(p, m, buffer);
  EXPECT_NEAR(r.pathLength, 20.0, 1e-9);
  for (const SimSample& s : buffer.data) ASSERT_TRUE(std::isfinite(s.x) && std::isfinite(s.fbX));
  expectWithinLimits(run(p, m), m);
}

TEST(Simulator, EmptyProgramGivesOneSampleAtRest) {
  const Machine m = defaultMachine();
  SampleBuffer buffer;
  const SimulationReport r = simulate(programOf({}), m, buffer);
  EXPECT_GE(r.samples, 1u);
  EXPECT_EQ(r.machiningTime, (r.samples - 1) * m.cycle);
}

TEST(Simulator, ServoFeedbackFollowsTheCommandWithASmallLag) {
  const Machine m = defaultMachine();
  SampleBuffer buffer;
  simulate(programOf({line(Vec3(100, 0, 0), 3000, 1)}), m, buffer);
  const auto& s = buffer.data;
  const SimSample& mid = s[s.size() / 2];  // cruising at 50 mm/s
  const AxisLimits& x = m.axes[0];
  const double steadyLag = 50.0 * (1 - x.velocityFeedForward) / x.positionGain;
  EXPECT_NEAR(mid.x - mid.fbX, steadyLag, 0.2 * steadyLag + 1e-4);
  EXPECT_NEAR(s.back().x, 100.0, 1e-12);
  EXPECT_LT(std::abs(s.back().fbX - 100.0), 0.05);  // still settling when the command ends
}

TEST(Simulator, WritesABiipDumpThatReadsBack) {
  const Machine m = defaultMachine();
  const Program p = parse("G1 X10 Y5 F2000\nG2 X20 Y5 R5\nG0 Z5\n");
  const std::string path = (isurface::test::scratchDir() / "sim.biip").string();
  const SimulationReport r = simulateToBiip(p, m, path);
  BiipReader reader(path);
  EXPECT_EQ(reader.recordCount(), r.samples);
  EXPECT_DOUBLE_EQ(reader.header().cycleSeconds, m.cycle);
  for (const char* name : {"line", "x", "y", "z", "fb_x", "fb_y", "fb_z", "feed"})
    EXPECT_TRUE(reader.hasChannel(name)) << name;
  const BiipChannelView x = reader.channel("x"), line = reader.channel("line");
  EXPECT_NEAR(x[reader.recordCount() - 1], 20.0, 1e-9);
  EXPECT_EQ(line[0], 1.0);
  EXPECT_EQ(line[reader.recordCount() - 1], 3.0);
}

// The servo's answer to a bend, as the optimiser plans with it: a whole simulated circle (G2 in
// XY and in XZ) deviates from the commanded path along its normal, read at the same instant, by
// the response times the normal acceleration v^2 / R, over the circle's steady part.
TEST(Simulator, ServoDeviationOnACircleIsItsResponseTimesTheNormalAcceleration) {
  const Machine m = defaultMachine();
  const double response = servoDeviationPerNormalAcceleration(m);  // um per mm/s^2
  ASSERT_GT(response, 0.0);
  ASSERT_LT(response, 1.0);
  for (const char* plane : {"G17 G2 X5 Y0 I-5 J0", "G18 G2 X5 Z0 I-5 K0"})
    for (const double feed : {900.0, 1800.0}) {
      const std::string f = " F" + std::to_string(static_cast<int>(feed)) + "\n";
      const std::string text = "G21 G90 G1 X5 Y0 Z0" + f + plane + f + plane + f + plane + f + "M30\n";
      SampleBuffer buffer;
      simulate(parse(text), m, buffer);
      const auto& s = buffer.data;
      double worst = 0, path = 0;
      const std::size_t from = s.size() / 3, to = 2 * s.size() / 3;  // the second circle, at speed
      for (std::size_t i = from; i < to; ++i) {
        const Vec3 commanded(s[i].x, s[i].y, s[i].z), feedback(s[i].fbX, s[i].fbY, s[i].fbZ);
        const Vec3 radial = commanded.normalized();
        worst = std::max(worst, std::abs((feedback - commanded).dot(radial)) * 1000.0);
        path += (Vec3(s[i + 1].x, s[i + 1].y, s[i + 1].z) - commanded).norm();
      }
      const double v = path / (double(to - from) * m.cycle);  // mm/s: the planner may hold it below F
      EXPECT_GT(v, 0.5 * mmPerMinToMmPerS(feed));
      EXPECT_NEAR(worst, response * v * v / 5.0, 0.2 * response * v * v / 5.0) << plane << " F" << feed;
    }
}
