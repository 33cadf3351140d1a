// A pass's corners cut by arcs inside a tube: no velocity step left, never further than the tube.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/optimise/polyline_distance.h"
#include "isurface/optimise/rounded_corners.h"

namespace isurface {
namespace {

// A relief sampled on a 0.375 mm grid along X whose slope changes at every point (heights of a
// smooth bump quantised to 0.05 mm, as a height map's are), in the plane Y = 2.
std::vector<Vec3> gridRelief(int count) {
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) {
    const double x = 0.375 * k;
    points.emplace_back(x, 2.0, std::round(20 * 2.0 * std::sin(x / 2.5)) / 20);
  }
  return points;
}

// rad, the turn of the path at point k.
double turnAt(const std::vector<Vec3>& points, std::size_t k) {
  const Vec3 a = (points[k] - points[k - 1]).normalized(), b = (points[k + 1] - points[k]).normalized();
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
}

double largestTurn(const std::vector<Vec3>& points) {
  double largest = 0;
  for (std::size_t k = 1; k + 1 < points.size(); ++k) largest = std::max(largest, turnAt(points, k));
  return largest;
}

// mm, distance from `p` to the segment from `a` to `b`.
double toSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

TEST(roundedCorners, AGridReliefTurnsInSmallStepsWithinItsTube) {
  const std::vector<Vec3> old = gridRelief(60);
  const double tube = 0.008, pieceTurn = 0.1;
  const RoundedPath rounded = roundedCorners(old, tube, pieceTurn);
  ASSERT_GT(largestTurn(old), 0.2);  // the grid's corners, as the relief's slope changes
  EXPECT_EQ(rounded.points.front(), old.front());
  EXPECT_EQ(rounded.points.back(), old.back());
  EXPECT_GT(rounded.points.size(), old.size());
  EXPECT_LE(largestTurn(rounded.points), pieceTurn + 1e-9);
  // Both ways: every new point near the old path, and every old corner near the new one.
  EXPECT_LE(polylineDistance(rounded.points, old), tube + 1e-9);
  // The tube is used where a corner is sharp enough to need it (so it rounds what it can).
  EXPECT_GT(polylineDistance(old, rounded.points), 0.5 * tube);
  for (const Vec3& p : rounded.points) EXPECT_DOUBLE_EQ(p.y(), 2.0);  // the pass stays in its plane
}

TEST(roundedCorners, EachNewSegmentNamesTheOldOneItLiesAlong) {
  const std::vector<Vec3> old = gridRelief(30);
  const RoundedPath rounded = roundedCorners(old, 0.008, 0.1);
  ASSERT_EQ(rounded.oldSegment.size(), rounded.points.size() - 1);
  EXPECT_EQ(rounded.oldSegment.front(), 0u);
  EXPECT_EQ(rounded.oldSegment.back(), old.size() - 2);
  for (std::size_t k = 0; k < rounded.oldSegment.size(); ++k) {
    if (k > 0) {
      EXPECT_GE(rounded.oldSegment[k], rounded.oldSegment[k - 1]) << k;
    }
    const std::size_t s = rounded.oldSegment[k];
    ASSERT_LT(s + 1, old.size());
    // A piece of an arc lies near the leg it stands for, within the tube of its corner.
    const Vec3 middle = 0.5 * (rounded.points[k] + rounded.points[k + 1]);
    EXPECT_LE(toSegment(middle, old[s], old[s + 1]), 0.008) << k;
  }
}

TEST(roundedCorners, ASharpCornersSmallArcIsCutIntoFewerLongerChords) {
  // At 1.2 rad the arc within 8 um of the corner is about 45 um long: chords of 0.1 rad would be
  // 4 um, shorter than the 0.25 um of a program's last decimal can aim. Every corner sharper
  // than a few tenths of a radian has such a short arc.
  for (const double turn : {0.35, 0.6, 0.95, 1.2, 1.3, 2.0, 2.7}) {
    const std::vector<Vec3> corner = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1 + std::cos(turn), 0, std::sin(turn))};
    const RoundedPath r = roundedCorners(corner, 0.008, 0.1);
    ASSERT_GT(r.points.size(), 3u) << turn;
    // Chords of 20 um or more; a corner so sharp that its whole arc is shorter is one chord.
    for (std::size_t k = 2; r.points.size() > 4 && k + 1 < r.points.size(); ++k) {
      EXPECT_GE((r.points[k] - r.points[k - 1]).norm(), 0.02 - 1e-12) << turn << " " << k;  // mm
    }
    EXPECT_LE(polylineDistance(corner, r.points), 0.008 + 1e-9) << turn;
    EXPECT_LE(polylineDistance(r.points, corner), 0.008 + 1e-9) << turn;
    EXPECT_GT(polylineDistance(corner, r.points), 0.006) << turn;
  }
}

TEST(roundedCorners, ArcsThatShareAShortLegMeetInItsMiddle) {
  // Legs of 0.06 mm turning by 0.5 rad in turn: each arc wants more than half of each leg.
  std::vector<Vec3> zig;
  for (int k = 0; k < 8; ++k) zig.emplace_back(0.06 * k, 0.0, (k % 2) * 0.015);
  const RoundedPath r = roundedCorners(zig, 0.008, 0.1);
  for (std::size_t k = 1; k < r.points.size(); ++k)
    EXPECT_GT((r.points[k] - r.points[k - 1]).norm(), 0.005) << k;  // no sliver, no doubled point
  EXPECT_EQ(r.oldSegment.size(), r.points.size() - 1);
  EXPECT_LE(polylineDistance(zig, r.points), 0.008 + 1e-9);
  EXPECT_LE(polylineDistance(r.points, zig), 0.008 + 1e-9);
}

TEST(roundedCorners, ShortLegsAndSlightCornersAreLeftTheirShape) {
  // Legs of 10 um: the arc takes less than half of each, so no two points coincide and the
  // corner is cut by less than the tube.
  const std::vector<Vec3> shortLegs = {Vec3(0, 0, 0), Vec3(0.01, 0, 0), Vec3(0.02, 0, 0.01), Vec3(0.03, 0, 0.01)};
  const RoundedPath r = roundedCorners(shortLegs, 0.008, 0.1);
  for (std::size_t k = 1; k < r.points.size(); ++k) EXPECT_GT((r.points[k] - r.points[k - 1]).norm(), 1e-4) << k;
  EXPECT_LE(polylineDistance(r.points, shortLegs), 0.008);
  EXPECT_LE(polylineDistance(shortLegs, r.points), 0.008);
  // A corner slighter than one piece's turn is already as smooth as an arc's junctions.
  const std::vector<Vec3> slight = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0.05)};
  EXPECT_EQ(roundedCorners(slight, 0.008, 0.1).points, slight);
  // A turn back (a zig-zag raster's end) is not a corner to cut.
  const std::vector<Vec3> back = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0.01, 0)};
  EXPECT_EQ(roundedCorners(back, 0.008, 0.1).points, back);
}

TEST(roundedCorners, DegenerateInputsComeBackUnchangedOrFinite) {
  EXPECT_TRUE(roundedCorners({}, 0.008, 0.1).points.empty());
  const std::vector<Vec3> two = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  EXPECT_EQ(roundedCorners(two, 0.008, 0.1).points, two);
  const std::vector<Vec3> grid = gridRelief(10);
  EXPECT_EQ(roundedCorners(grid, 0.0, 0.1).points, grid);
  EXPECT_EQ(roundedCorners(grid, 0.008, 0.0).points, grid);
  // Duplicate points (a CAM system writing the same point twice): the corners beside them are
  // kept, the others rounded, nothing is lost.
  const std::vector<Vec3> repeated = {Vec3(0, 0, 0), Vec3(0.4, 0, 0), Vec3(0.4, 0, 0), Vec3(0.8, 0, 0.2),
                                      Vec3(1.2, 0, 0.2), Vec3(1.6, 0, 0.5)};
  const RoundedPath r = roundedCorners(repeated, 0.008, 0.1);
  ASSERT_EQ(r.oldSegment.size(), r.points.size() - 1);
  for (const Vec3& p : r.points) EXPECT_TRUE(p.allFinite());
  EXPECT_LE(polylineDistance(r.points, repeated), 0.008 + 1e-9);
  EXPECT_LE(polylineDistance(repeated, r.points), 0.008 + 1e-9);
  EXPECT_GT(r.points.size(), repeated.size());
}

}  // namespace
}  // namespace isurface
