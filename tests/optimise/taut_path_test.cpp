// A pass's points drawn taut inside a tube: flatter corners, never further than the tube.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/optimise/polyline_distance.h"
#include "isurface/optimise/taut_path.h"

namespace isurface {
namespace {

// Points `step` mm apart along X whose Z steps up and down by `amplitude` (mm) in turn, as a
// relief sampled from a noisy height map.
std::vector<Vec3> zigZag(int count, double step, double amplitude) {
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) points.emplace_back(k * step, 1.0, (k % 2 == 0 ? 0.5 : -0.5) * amplitude);
  return points;
}

// rad, the largest turn of the path at its points `skip` or more points from either end.
double largestTurn(const std::vector<Vec3>& points, std::size_t skip = 1) {
  double largest = 0;
  for (std::size_t k = skip; k + skip < points.size(); ++k) {
    const Vec3 a = (points[k] - points[k - 1]).normalized(), b = (points[k + 1] - points[k]).normalized();
    largest = std::max(largest, std::acos(std::clamp(a.dot(b), -1.0, 1.0)));
  }
  return largest;
}

TEST(tautPath, AZigZagTurnsLessAndStaysInItsTube) {
  const std::vector<Vec3> old = zigZag(40, 0.15, 0.04);
  const double radius = 0.008;
  const std::vector<Vec3> taut = drawnTaut(old, radius);
  ASSERT_EQ(taut.size(), old.size());
  EXPECT_EQ(taut.front(), old.front());
  EXPECT_EQ(taut.back(), old.back());
  for (std::size_t k = 0; k < old.size(); ++k) EXPECT_LE((taut[k] - old[k]).norm(), radius + 1e-12) << k;
  EXPECT_LE(polylineDistance(taut, old), radius + 1e-12);
  // 40 um steps every 0.15 mm turn by 0.52 rad; 16 um of them taken out leaves 0.32 rad (next
  // to the ends, which stay, the turn is a little larger).
  EXPECT_NEAR(largestTurn(old), 0.52, 0.01);
  EXPECT_NEAR(largestTurn(taut, 3), 0.32, 0.01);
  EXPECT_LT(largestTurn(taut), 0.4);
  for (const Vec3& p : taut) EXPECT_DOUBLE_EQ(p.y(), 1.0);  // the pass stays in its plane
}

TEST(tautPath, StepsSmallerThanTheTubeAreFlattenedAway) {
  const std::vector<Vec3> old = zigZag(41, 0.15, 0.01);
  const std::vector<Vec3> taut = drawnTaut(old, 0.008);
  // 10 um steps, 8 um of tube on either side: the steps are gone, the path is nearly straight.
  EXPECT_NEAR(largestTurn(old), 0.13, 0.01);
  EXPECT_LT(largestTurn(taut, 4), 0.003);
  EXPECT_LT(largestTurn(taut), 0.02);  // next to the ends, which stay where they were
}

TEST(tautPath, ASmoothPathIsLeftWhereItIs) {
  // A straight line with its points unevenly spaced stays exactly where it is (each point is
  // already where the chord between its neighbours passes at its share of their distance; the
  // middle of that chord would slide it along the line), and an arc of 20 mm radius moves by far
  // less than the tube.
  std::vector<Vec3> line, arc;
  for (int k = 0; k < 30; ++k) {
    const double s = 0.2 * k + (k % 3 == 0 ? 0.05 : 0.0);
    line.emplace_back(s, 0.5 * s, -0.25 * s);
    arc.emplace_back(20 * std::sin(s / 20), 0.0, 20 * (1 - std::cos(s / 20)));
  }
  const std::vector<Vec3> tautLine = drawnTaut(line, 0.008);
  for (std::size_t k = 0; k < line.size(); ++k) EXPECT_LT((tautLine[k] - line[k]).norm(), 1e-12) << k;
  EXPECT_LT(polylineDistance(drawnTaut(arc, 0.008), arc), 0.002);
}

TEST(tautPath, DegenerateInputsComeBackUnchangedOrFinite) {
  const std::vector<Vec3> two = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  EXPECT_EQ(drawnTaut(two, 0.008), two);
  EXPECT_TRUE(drawnTaut({}, 0.008).empty());
  const std::vector<Vec3> zig = zigZag(10, 0.15, 0.04);
  EXPECT_EQ(drawnTaut(zig, 0.0), zig);
  EXPECT_EQ(drawnTaut(zig, -1.0), zig);
  // Duplicate points (a CAM system writing the same point twice) and the same point at both
  // ends (a closed contour).
  const std::vector<Vec3> repeated = {Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0.1, 0, 0.02), Vec3(0.1, 0, 0.02),
                                      Vec3(0.2, 0, 0), Vec3(0, 0, 0)};
  const std::vector<Vec3> taut = drawnTaut(repeated, 0.008);
  ASSERT_EQ(taut.size(), repeated.size());
  EXPECT_EQ(taut.front(), repeated.front());
  EXPECT_EQ(taut.back(), repeated.back());
  for (std::size_t k = 0; k < taut.size(); ++k) {
    EXPECT_TRUE(taut[k].allFinite()) << k;
    EXPECT_LE((taut[k] - repeated[k]).norm(), 0.008 + 1e-12) << k;
  }
}

}  // namespace
}  // namespace isurface
