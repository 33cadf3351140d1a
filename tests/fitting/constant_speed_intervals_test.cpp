// Constant speed intervals: characteristic points, ratios, intervals, and program sections.
#include "isurface/fitting/constant_speed_intervals.h"
#include "isurface/base/units.h"

#include <gtest/gtest.h>

#include <cmath>

#include "gcode_test_support.h"
#include "isurface/nc/feed_plan.h"

namespace isurface {
namespace {

using gcodetest::interpret;

// Builds the 29-point segment of the paper's section 6.1 in spirit (all mm):
//   run 1: P0..P7, 8 points 1 mm apart along +x;
//   transition 1: P8..P10, on an arc of radius 4 tangent to run 1 at P7, 22.5 degrees apart,
//     so P11 (the arc's end, 90 degrees on) ends it; chord c = 2*4*sin(11.25 deg) = 1.561;
//   run 2: P11..P17, 7 points 1 mm apart, leaving the arc with a 45 degree corner at P11;
//   transition 2 and run 3 (P18..P20, P21..P28): the same, mirrored (turning the other way).
std::vector<Vec3> paperLikeSegment() {
  std::vector<Vec3> p;
  Vec3 at(0, 0, 0);
  double heading = 0;
  auto run = [&](int count, bool includeStart) {
    const Vec3 d(std::cos(heading), std::sin(heading), 0);
    for (int k = includeStart ? 0 : 1; k < count; ++k) p.push_back(at + k * d);
    at = at + (count - 1) * d;
  };
  auto transition = [&](int sign) {
    const double r = 4, step = 22.5 * kPi / 180;
    const Vec3 normal(-std::sin(heading), std::cos(heading), 0);
    const Vec3 centre = at + sign * r * normal;
    const Vec3 radial = at - centre;
    for (int k = 1; k <= 4; ++k) {
      const double a = sign * step * k;
      const Vec3 q = centre + Vec3(radial.x() * std::cos(a) - radial.y() * std::sin(a),
                                   radial.x() * std::sin(a) + radial.y() * std::cos(a), 0);
      if (k < 4) p.push_back(q);
      else at = q;
    }
    heading += sign * (90.0 + 45.0) * kPi / 180;  // the arc's 90 degrees, then the corner
    p.push_back(at);
  };
  run(8, true);
  transition(+1);
  run(7, false);
  transition(-1);
  run(8, false);
  return p;
}

double curvatureAt(const std::vector<Vec3>& p, std::size_t i) {
  const double r = threePointRadius(p[i - 1], p[i], p[i + 1]);
  return std::isfinite(r) ? 1.0 / r : 0.0;
}

TEST(constantSpeedIntervals, paperLikeSegmentGivesRunsAndTransitions) {
  const std::vector<Vec3> p = paperLikeSegment();
  ASSERT_EQ(p.size(), 29u);
  // Why the answer is what it is (k = curvature from equation 1, mm^-1):
  //  - Characteristic points (E_thr = 0.1): straight-run interiors lie on the chord between the
  //    run's ends (deviation 0) and drop out; each arc point is 4 (1 - cos 22.5) = 0.30 mm off
  //    the chord of its neighbours, and every run end is a corner, so they all stay: P0, P7..P11,
  //    P17..P21, P28 (12 points).
  //  - P7 (run 1 -> arc, tangent): k7 = 2 sin(11.25) / |P8 - P6| = 0.390 / 2.549 = 0.153 while
  //    k6 = 0 (straight): ratio "large" -> boundary. Likewise P17.
  //  - P8: k8 = 1/4 (P7, P8, P9 on the arc), Q = 0.25 / 0.153 = 1.63 < 2 -> inside.
  //  - P9, P10: three points on the arc, Q = 1 -> inside. (P11 is on the arc too, so k10 = 1/4.)
  //  - P11 (arc -> run 2 with a 45 degree corner): the turn there is 11.25 + 45 = 56.25 degrees,
  //    |P12 - P10|^2 = 1.561^2 + 1 + 2 * 1.561 cos 56.25 -> 2.274, k11 = 2 sin 56.25 / 2.274 =
  //    0.731, Q = 0.731 / 0.25 = 2.93 > 2 -> boundary. Likewise P21.
  //  - Distance ratios stay within (1/5, 5): 1.561 at P7 and P17, 1 on the arcs, 0.64 at P11/P21.
  //  So the boundaries are P0, P7, P11, P17, P21, P28 and the intervals are run 1 [0,7],
  //  transition 1 [7,11], run 2 [11,17], transition 2 [17,21], run 3 [21,28].
  const IntervalPartition part = partitionConstantSpeedIntervals(p, {0.1, 5, 2});
  std::vector<std::size_t> characteristic, boundaries;
  for (const CharacteristicPoint& c : part.characteristic) {
    characteristic.push_back(c.index);
    if (!c.inside) boundaries.push_back(c.index);
  }
  EXPECT_EQ(characteristic, (std::vector<std::size_t>{0, 7, 8, 9, 10, 11, 17, 18, 19, 20, 21, 28}));
  EXPECT_EQ(boundaries, (std::vector<std::size_t>{0, 7, 11, 17, 21, 28}));
  ASSERT_EQ(part.intervals.size(), 5u);
  const std::size_t expected[5][2] = {{0, 7}, {7, 11}, {11, 17}, {17, 21}, {21, 28}};
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(part.intervals[k].first, expected[k][0]) << k;
    EXPECT_EQ(part.intervals[k].last, expected[k][1]) << k;
  }
  // Hand values of the ratios above.
  const auto& c = part.characteristic;
  EXPECT_NEAR(c[1].radius, 1 / 0.1531, 0.01);
  EXPECT_NEAR(c[1].distanceRatio, 1.561, 0.001);
  EXPECT_GE(c[1].curvatureRatio, kLargeRatio);
  EXPECT_NEAR(c[2].curvatureRatio, 1.633, 0.005);
  EXPECT_NEAR(c[3].curvatureRatio, 1.0, 1e-9);
  EXPECT_NEAR(c[5].curvatureRatio, 2.93, 0.01);
  EXPECT_NEAR(c[5].distanceRatio, 1 / 1.561, 0.001);
  // Average curvature: run 1 has only its end P7 curved (P0 copies P1's zero), 8 points.
  EXPECT_NEAR(part.intervals[0].averageCurvature, curvatureAt(p, 7) / 8, 1e-12);
  const double transition =
      (curvatureAt(p, 7) + curvatureAt(p, 8) + curvatureAt(p, 9) + curvatureAt(p, 10) + curvatureAt(p, 11)) / 5;
  EXPECT_NEAR(part.intervals[1].averageCurvature, transition, 1e-12);
  EXPECT_NEAR(part.intervals[0].length, 7.0, 1e-12);
  EXPECT_NEAR(part.intervals[1].length, 4 * 1.5607, 1e-3);
}

TEST(constantSpeedIntervals, duplicatesAreSkippedAndIndicesStayOriginal) {
  std::vector<Vec3> p = paperLikeSegment();
  p.insert(p.begin() + 8, p[7]);  // P7 twice: every later index moves by one
  p.insert(p.begin(), p[0]);      // P0 twice
  const IntervalPartition part = partitionConstantSpeedIntervals(p, {0.1, 5, 2});
  ASSERT_EQ(part.intervals.size(), 5u);
  EXPECT_EQ(part.intervals[0].first, 0u);
  EXPECT_EQ(part.intervals[0].last, 8u);  // P7, now at 8 (its first copy)
  EXPECT_EQ(part.intervals[1].last, 13u);
  EXPECT_EQ(part.intervals[4].last, 30u);
}

TEST(constantSpeedIntervals, fewPointsAndStraightLines) {
  EXPECT_TRUE(partitionConstantSpeedIntervals({}).intervals.empty());
  EXPECT_TRUE(partitionConstantSpeedIntervals({Vec3(1, 2, 3)}).intervals.empty());
  EXPECT_TRUE(partitionConstantSpeedIntervals({Vec3(1, 2, 3), Vec3(1, 2, 3)}).intervals.empty());
  const auto two = partitionConstantSpeedIntervals({Vec3(0, 0, 0), Vec3(3, 4, 0)});
  ASSERT_EQ(two.intervals.size(), 1u);
  EXPECT_EQ(two.intervals[0].last, 1u);
  EXPECT_DOUBLE_EQ(two.intervals[0].length, 5.0);
  std::vector<Vec3> line;
  for (int i = 0; i < 10; ++i) line.push_back(Vec3(i, 2 * i, 0));
  const auto straight = partitionConstantSpeedIntervals(line);
  ASSERT_EQ(straight.intervals.size(), 1u);
  EXPECT_EQ(straight.characteristic.size(), 2u);
  EXPECT_EQ(straight.intervals[0].averageCurvature, 0.0);
  EXPECT_TRUE(std::isinf(straight.characteristic[0].radius));
}

TEST(constantSpeedIntervals, ratioGuardsAndThresholds) {
  EXPECT_EQ(curvatureRatio(0, 0), 1.0);
  EXPECT_EQ(curvatureRatio(0.5, 0), kLargeRatio);
  EXPECT_EQ(curvatureRatio(0, 0.5), 1.0 / kLargeRatio);
  EXPECT_DOUBLE_EQ(curvatureRatio(0.5, 0.25), 2.0);
  EXPECT_THROW(partitionConstantSpeedIntervals(paperLikeSegment(), {0, 5, 2}), InputError);
  EXPECT_THROW(partitionConstantSpeedIntervals(paperLikeSegment(), {0.1, 1, 2}), InputError);
  EXPECT_THROW(partitionConstantSpeedIntervals(paperLikeSegment(), {0.1, 5, -2}), InputError);
}

TEST(constantSpeedIntervals, douglasPeuckerKeepsEndsAndCorners) {
  const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0.05, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(2, 2, 0)};
  EXPECT_EQ(douglasPeuckerIndices(p, 0.1), (std::vector<std::size_t>{0, 2, 4}));
  EXPECT_EQ(douglasPeuckerIndices(p, 0.01), (std::vector<std::size_t>{0, 1, 2, 4}));
}

TEST(constantSpeedIntervals, rasterSectionsSplitAtPassReversals) {
  // Three raster passes along X joined by 1 mm step-overs in Y; the approach is a rapid.
  const Program program = interpret(
      "G21 G90\nG0 X0 Y0 Z0\nG1 X10 F600\nY1\nX0\nY2\nX10\nM2\n");
  const auto sections = collectSections(program, 1, 100);
  ASSERT_EQ(sections.size(), 3u);
  EXPECT_EQ(sections[0].points.size(), 3u);  // (0,0) (10,0) (10,1)
  EXPECT_TRUE(sections[1].points.front().isApprox(Vec3(10, 1, 0)));
  EXPECT_TRUE(sections[1].points.back().isApprox(Vec3(0, 2, 0)));
  EXPECT_TRUE(sections[2].points.back().isApprox(Vec3(10, 2, 0)));
  // Lines 3..4 only: the first pass and its step-over.
  const auto part = collectSections(program, 3, 4);
  ASSERT_EQ(part.size(), 1u);
  EXPECT_EQ(part[0].lines, (std::vector<std::uint32_t>{3, 3, 4}));
  EXPECT_TRUE(collectSections(program, 1, 2).empty());  // only rapids there
}

TEST(constantSpeedIntervals, pathWithoutBoundarySplitsByDistanceAndArcsAreSampled) {
  // A long line in +X, then a quarter arc of radius 10 turning to +Y (no reversal).
  const Program program = interpret("G21 G90\nG0 X0 Y0\nG1 X120 F600\nG3 X130 Y10 I0 J10\nM2\n");
  SectionOptions options;
  const auto sections = collectSections(program, 1, 100, options);
  // 120 mm of line plus 15.7 mm of arc: the line's end (at 120) passes 50 mm at once, so each
  // section ends at the previous CL point.
  ASSERT_GE(sections.size(), 2u);
  // Arc chords within 0.001 mm: angle step <= 2 acos(1 - 0.001 / 10) = 0.02828 rad -> 56 steps.
  std::size_t arcPoints = 0;
  for (const auto& s : sections)
    for (std::size_t i = 0; i < s.points.size(); ++i)
      if (s.lines[i] == 4) ++arcPoints;
  EXPECT_GE(arcPoints, 56u);
  for (const auto& s : sections)
    for (std::size_t i = 1; i < s.points.size(); ++i) {
      if (s.lines[i] != 4 || s.lines[i - 1] != 4) continue;
      const Vec3 mid = 0.5 * (s.points[i] + s.points[i - 1]);
      EXPECT_LE(10.0 - (mid - Vec3(120, 10, 0)).norm(), 0.001 + 1e-12);
    }
}

}  // namespace
}  // namespace isurface
