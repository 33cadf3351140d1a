#include "isurface/optimise/points_on_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "isurface/base/tolerances.h"

namespace isurface {

namespace {

// Of the shorter piece beside a point, how far it may slide along the path either way: near the
// point, where the parabola through it and its neighbours follows the path even when one of them
// is far (a long straight met by a bend).
constexpr double kSlideShare = 0.25;
// Positions tried along the slide. On a bend of radius 300 mm in pieces of 0.05 mm written to
// 0.1 um, the curvature through three points is off by up to 0.013/mm with the best of 64, and
// 0.004/mm with the best of 256 (0.06/mm rounded where they stand).
constexpr int kSlidePositions = 256;
// Of the grid's step, how far off the path a place is good enough to stop looking (about the
// best of 256 on average).
constexpr double kGoodEnough = 1.0 / 256;

Vec3 rounded(const Vec3& p, double grid) {
  return Vec3(std::round(p.x() / grid) * grid, std::round(p.y() / grid) * grid, std::round(p.z() / grid) * grid);
}

// The parabola through a, b, c in chord length (a at 0, b at `ab`, c at `ab + bc`): its point
// and unit tangent at `t`.
struct Parabola {
  Vec3 a, b, c;
  double t1, t2;
  Vec3 at(double t) const {
    return a * ((t - t1) * (t - t2) / (t1 * t2)) + b * (t * (t - t2) / (t1 * (t1 - t2))) + c * (t * (t - t1) / (t2 * (t2 - t1)));
  }
  Vec3 tangent(double t) const {
    const Vec3 d = a * ((2 * t - t1 - t2) / (t1 * t2)) + b * ((2 * t - t2) / (t1 * (t1 - t2))) + c * ((2 * t - t1) / (t2 * (t2 - t1)));
    return d.normalized();
  }
};

}  // namespace

std::vector<Vec3> pointsOnGrid(const std::vector<Vec3>& points, double grid) {
  std::vector<Vec3> out(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    out[k] = rounded(points[k], grid);
    if (k == 0 || k + 1 == points.size()) continue;
    const double ab = (points[k] - points[k - 1]).norm(), bc = (points[k + 1] - points[k]).norm();
    if (!(ab > kLengthEpsilon) || !(bc > kLengthEpsilon)) continue;
    const Parabola curve{points[k - 1], points[k], points[k + 1], ab, ab + bc};
    double bestOff = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= kSlidePositions; ++i) {
      // From a quarter of the piece before to a quarter of the piece after, the point itself
      // tried first so that it stays where nothing is gained.
      const int j = i == 0 ? kSlidePositions / 2 : i - 1 + (i - 1 >= kSlidePositions / 2);
      const double s = double(j) / kSlidePositions;
      const double t = ab + kSlideShare * std::min(ab, bc) * (2 * s - 1);
      const Vec3 p = curve.at(t), r = rounded(p, grid), d = r - p, along = curve.tangent(t);
      const double off = (d - d.dot(along) * along).norm();
      if (off < bestOff - kLengthEpsilon * 1e-3) bestOff = off, out[k] = r;
      if (bestOff <= kGoodEnough * grid) break;
    }
  }
  return out;
}

}  // namespace isurface
