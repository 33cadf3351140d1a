// The distance between an old and a new tool path, against every segment tried.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "isurface/optimise/polyline_distance.h"

namespace isurface {
namespace {

double bruteOneWay(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
  double worst = 0;
  for (const Vec3& p : from) {
    double best = to.size() == 1 ? (to[0] - p).norm() : INFINITY;
    for (std::size_t k = 0; k + 1 < to.size(); ++k) {
      const Vec3 d = to[k + 1] - to[k];
      const double l2 = d.squaredNorm();
      const double t = l2 > 0 ? std::clamp((p - to[k]).dot(d) / l2, 0.0, 1.0) : 0.0;
      best = std::min(best, (to[k] + t * d - p).norm());
    }
    worst = std::max(worst, best);
  }
  return worst;
}

double brute(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return std::max(bruteOneWay(a, b), bruteOneWay(b, a));
}

// A zig-zag raster over a wavy surface, its points `step` mm apart along X, shifted by `wobble`
// (mm) in a pattern of its own: a CAM program and a re-fit of it that strays by micrometres.
std::vector<Vec3> raster(int passes, double step, double wobble, double phase) {
  std::vector<Vec3> out;
  for (int k = 0; k < passes; ++k) {
    const double y = 0.4 * k;
    const int n = static_cast<int>(20.0 / step);
    for (int i = 0; i <= n; ++i) {
      const double x = (k % 2 == 0 ? i : n - i) * step;
      const double z = 2 * std::sin(0.3 * x) * std::cos(0.2 * y) + wobble * std::sin(7.0 * x + phase);
      out.emplace_back(x, y + wobble * std::cos(5.0 * x + phase), z);
    }
  }
  return out;
}

TEST(polylineDistance, IsTheLargestDistanceToTheOtherPathBothWays) {
  const std::vector<Vec3> old = raster(12, 0.25, 0, 0);
  const std::vector<Vec3> refitted = raster(12, 0.07, 0.006, 1.3);  // strays up to about 8 um
  const double d = polylineDistance(refitted, old);
  EXPECT_GT(d, 0.004);
  EXPECT_DOUBLE_EQ(d, brute(refitted, old));
  EXPECT_DOUBLE_EQ(polylineDistance(old, refitted), d);
}

// A finishing path run twice, the second time 3 um lower, and its re-fit run the other way
// round (the lower run first): each point's nearest segment lies far down the other path from
// where the points before it were matched, with a segment of the wrong run 3 um away on the way.
TEST(polylineDistance, APathRunTwiceIsMatchedWithTheNearerRun) {
  const Vec3 lower(0, 0, 0.003);
  std::vector<Vec3> old = raster(6, 0.05, 0, 0);
  const std::size_t once = old.size();
  for (std::size_t i = 0; i < once; ++i) old.push_back(old[i] - lower);
  std::vector<Vec3> refitted = raster(6, 0.08, 0.0008, 0.7);
  const std::size_t refittedOnce = refitted.size();
  for (std::size_t i = 0; i < refittedOnce; ++i) refitted.push_back(refitted[i]);
  for (std::size_t i = 0; i < refittedOnce; ++i) refitted[i] -= lower;
  const double d = polylineDistance(refitted, old);
  EXPECT_DOUBLE_EQ(d, brute(refitted, old));
  EXPECT_LT(d, 0.0015);
}

TEST(polylineDistance, PathsThatDoNotRunAlikeAreMeasuredAllTheSame) {
  std::vector<Vec3> old = raster(8, 0.05, 0, 0);  // more points than a look around the last match covers
  std::vector<Vec3> other = raster(8, 0.11, 0.02, 0.4);
  std::reverse(other.begin(), other.end());  // cut the other way round
  other.emplace_back(5, 30, 1);              // and a point far from everything
  other.insert(other.begin() + 100, other[100]);  // a zero-length segment
  EXPECT_DOUBLE_EQ(polylineDistance(other, old), brute(other, old));
  EXPECT_DOUBLE_EQ(polylineDistance(old, {Vec3(1, 2, 3)}), brute(old, {Vec3(1, 2, 3)}));
  EXPECT_EQ(polylineDistance({}, old), 0);
}

}  // namespace
}  // namespace isurface
