// A pass's bends eased in and out: the curvature rises and falls over a stretch instead of
// stepping, never further than the tube from the program's path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/optimise/eased_path.h"
#include "isurface/optimise/polyline_distance.h"

namespace isurface {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 5.0;  // mm
constexpr double kSweep = 25 * kPi / 180;

// A plane, a fillet of 5 mm over 25 degrees and a slope along X: the fillet's points placed by a
// chord tolerance of `chord` mm (as a CAM system places them) or, finely, on the arc itself.
std::vector<Vec3> planeFilletSlope(double chord) {
  const int pieces = static_cast<int>(std::ceil(kSweep / (2 * std::acos(1 - chord / kRadius))));
  std::vector<Vec3> points = {Vec3(0, 3, 0)};
  for (int k = 0; k <= pieces; ++k) {
    const double a = kSweep * k / pieces;
    points.emplace_back(20 + kRadius * std::sin(a), 3, kRadius * (1 - std::cos(a)));
  }
  const Vec3 end = points.back();
  points.push_back(end + 20 * Vec3(std::cos(kSweep), 0, std::sin(kSweep)));
  return points;
}

// 1/mm, the curvature at point k: one over the radius of the circle through it and its neighbours.
double curvatureAt(const std::vector<Vec3>& p, std::size_t k) {
  return 1.0 / threePointRadius(p[k - 1], p[k], p[k + 1]);
}

}  // namespace

TEST(easedPath, AFilletMeetsItsPlaneAndSlopeWithoutAStepOfCurvature) {
  const std::vector<Vec3> program = planeFilletSlope(0.005), smooth = planeFilletSlope(1e-6);
  const EasedPath eased = easedPath(smooth, program, {0.008, 0.005, 0.01, 0.01});
  EXPECT_LE(polylineDistance(eased.points, program), 0.008);
  EXPECT_GT(eased.window, 0.3);  // mm: the tube lets the bend ease in over a few tenths of a mm
  EXPECT_EQ(eased.points.front(), program.front());
  EXPECT_EQ(eased.points.back(), program.back());
  ASSERT_EQ(eased.oldSegment.size() + 1, eased.points.size());
  // Along the path the curvature climbs from the plane's 0 to the fillet's 1/R in many small
  // steps, and no higher: the arc itself (the smooth path) steps from 0 to 1/R at once.
  double largestStep = 0, largest = 0;
  std::size_t easing = 0;  // points between a tenth and nine tenths of 1/R
  for (std::size_t k = 2; k + 1 < eased.points.size(); ++k) {
    const double c = curvatureAt(eased.points, k);
    largestStep = std::max(largestStep, std::abs(c - curvatureAt(eased.points, k - 1)));
    largest = std::max(largest, c);
    easing += c > 0.1 / kRadius && c < 0.9 / kRadius;
  }
  EXPECT_LT(largestStep, 0.25 / kRadius);
  EXPECT_LT(largest, 1.05 / kRadius);
  EXPECT_GE(easing, 10u);
  // Every new segment names the old one beside it.
  for (std::size_t k = 0; k + 1 < eased.points.size(); ++k) {
    const std::size_t s = eased.oldSegment[k];
    ASSERT_LT(s + 1, program.size());
    EXPECT_LE(distanceToSegment(0.5 * (eased.points[k] + eased.points[k + 1]), program[s], program[s + 1]), 0.0081) << k;
  }
}

TEST(easedPath, ATighterTubeEasesOverAShorterStretch) {
  const std::vector<Vec3> program = planeFilletSlope(0.005), smooth = planeFilletSlope(1e-6);
  const EasedPath wide = easedPath(smooth, program, {0.008, 0.005, 0.01});
  const EasedPath narrow = easedPath(smooth, program, {0.006, 0.005, 0.01});
  EXPECT_LT(narrow.window, wide.window);
  EXPECT_LE(polylineDistance(narrow.points, program), 0.006);
}

TEST(easedPath, AStraightRunStaysWhereItIs) {
  const std::vector<Vec3> line = {Vec3(0, 0, 0), Vec3(3, 1, 0.5), Vec3(9, 3, 1.5), Vec3(12, 4, 2)};
  const EasedPath eased = easedPath(line, line, {0.008, 0.005, 0.01});
  EXPECT_LT(polylineDistance(eased.points, line), 1e-9);
  EXPECT_EQ(eased.points.front(), line.front());
  EXPECT_EQ(eased.points.back(), line.back());
  EXPECT_GE(eased.window, 4.0);  // averaged over the widest window, and still straight
  EXPECT_EQ(eased.points.size(), 2u);
}

// A pass that ends inside a bend (a fillet cut off by the pass's end) keeps its end and eases
// into it: no kink where the averaging meets the end.
TEST(easedPath, APassEndingInABendEndsWithoutAKink) {
  std::vector<Vec3> program = planeFilletSlope(0.005), smooth = planeFilletSlope(1e-6);
  program.pop_back(), smooth.pop_back();  // no slope: the pass ends on the arc
  const EasedPath eased = easedPath(smooth, program, {0.008, 0.005, 0.01});
  EXPECT_EQ(eased.points.back(), program.back());
  EXPECT_LE(polylineDistance(eased.points, program), 0.008);
  for (std::size_t k = 1; k + 1 < eased.points.size(); ++k) {
    const Vec3 a = (eased.points[k] - eased.points[k - 1]).normalized(), b = (eased.points[k + 1] - eased.points[k]).normalized();
    EXPECT_LT(std::acos(std::clamp(a.dot(b), -1.0, 1.0)), 0.0125) << "point " << k << " of " << eased.points.size();
  }
  EXPECT_GT(eased.window, 0.5);  // the end does not narrow the window for the whole pass
}

// A plane the program wrote in many short moves: every new segment, even one chord across the
// whole plane, names a move beside it.
TEST(easedPath, EachNewSegmentNamesAnOldOneBesideIt) {
  std::vector<Vec3> program;
  for (int k = 0; k < 400; ++k) program.emplace_back(0.05 * k, 3, 0);
  const std::vector<Vec3> fillet = planeFilletSlope(0.005);
  program.insert(program.end(), fillet.begin() + 1, fillet.end());
  const EasedPath eased = easedPath(program, program, {0.008, 0.005, 0.01, 0.01});
  ASSERT_EQ(eased.oldSegment.size() + 1, eased.points.size());
  for (std::size_t k = 0; k + 1 < eased.points.size(); ++k) {
    const std::size_t s = eased.oldSegment[k];
    const Vec3 middle = 0.5 * (eased.points[k] + eased.points[k + 1]);
    EXPECT_LE(distanceToSegment(middle, program[s], program[s + 1]), 0.0081) << k;
  }
  // The bend (sharper than 0.01 /mm) is written in pieces of at most 0.05 mm.
  for (std::size_t k = 0; k + 1 < eased.points.size(); ++k) {
    if (eased.points[k].x() < 20.5 || eased.points[k].x() > 21.5) continue;
    EXPECT_LE((eased.points[k + 1] - eased.points[k]).norm(), 0.05 + 1e-9) << k;
  }
}

// Too few points, repeated points, no tube: the path comes back as it was, each segment named.
TEST(easedPath, DegeneratePathsComeBackUnchanged) {
  for (const std::vector<Vec3>& path : {std::vector<Vec3>{Vec3(0, 0, 0), Vec3(1, 0, 0)},
                                        std::vector<Vec3>{Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)}}) {
    const EasedPath eased = easedPath(path, path, {0.008, 0.005, 0.01});
    EXPECT_EQ(eased.points, path);
    EXPECT_EQ(eased.oldSegment.size() + 1, path.size());
  }
  const std::vector<Vec3> program = planeFilletSlope(0.005);
  const EasedPath none = easedPath(program, program, {0.0, 0.005, 0.01});
  EXPECT_EQ(none.points, program);
  EXPECT_EQ(none.window, 0.0);
}

}  // namespace isurface
