// Points of a smooth path written to a program's last decimal: placed where their rounding keeps
// them on the path, so that the curvature an NC estimates from three of them is the path's.
#include "isurface/optimise/points_on_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace isurface;

namespace {

constexpr double kGrid = 1e-4;  // mm, 4 decimals

// A bend of radius `r` in XZ, the kind an eased fillet flattens into, in pieces of `piece` (mm).
std::vector<Vec3> arc(double r, double piece, int count) {
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) {
    const double phi = 0.3 + piece * k / r;
    points.emplace_back(r * std::sin(phi), 12.5, r * (1 - std::cos(phi)));
  }
  return points;
}

Vec3 rounded(const Vec3& p) {
  return Vec3(std::round(p.x() / kGrid) * kGrid, std::round(p.y() / kGrid) * kGrid, std::round(p.z() / kGrid) * kGrid);
}

// The largest error of the curvature through three consecutive points (1/mm), against 1/r; not
// at the ends, which a program's path joins where they are (there, on its grid already).
double worstCurvatureError(const std::vector<Vec3>& p, double r) {
  double worst = 0;
  for (std::size_t k = 2; k + 2 < p.size(); ++k) {
    const Vec3 a = p[k - 1], b = p[k], c = p[k + 1];
    const double curvature = 2 * (b - a).cross(c - a).norm() / ((b - a).norm() * (c - b).norm() * (c - a).norm());
    worst = std::max(worst, std::fabs(curvature - 1 / r));
  }
  return worst;
}

}  // namespace

TEST(pointsOnGrid, ThreePointsGiveThePathsCurvatureAfterRounding) {
  const double r = 300;  // mm
  const std::vector<Vec3> points = arc(r, 0.05, 400);
  std::vector<Vec3> plain;
  for (const Vec3& p : points) plain.push_back(rounded(p));
  // Rounded where they stand, pieces of 0.05 mm carry curvatures of 0 to 1/25 mm.
  EXPECT_GT(worstCurvatureError(plain, r), 0.02);
  const std::vector<Vec3> placed = pointsOnGrid(points, kGrid);
  ASSERT_EQ(placed.size(), points.size());
  EXPECT_LT(worstCurvatureError(placed, r), 0.006);
}

TEST(pointsOnGrid, PointsStayOnThePathOnItsGridAndEndsStay) {
  const double r = 8;  // mm, a fillet
  const std::vector<Vec3> points = arc(r, 0.05, 200);
  const std::vector<Vec3> placed = pointsOnGrid(points, kGrid);
  EXPECT_EQ(placed.front(), rounded(points.front()));
  EXPECT_EQ(placed.back(), rounded(points.back()));
  for (std::size_t k = 0; k < placed.size(); ++k) {
    const Vec3& p = placed[k];
    // On the circle within the grid's rounding, and near where it was (a quarter of a piece).
    EXPECT_NEAR(std::hypot(p.x(), p.z() - r), r, 1e-4) << k;
    EXPECT_LT((p - points[k]).norm(), 0.25 * 0.05 + 1e-4) << k;
    for (const double v : {p.x(), p.y(), p.z()}) EXPECT_NEAR(v / kGrid, std::round(v / kGrid), 1e-6) << k;
  }
}

TEST(pointsOnGrid, RepeatedPointsAndShortPathsAreLeftRounded) {
  const std::vector<Vec3> repeated = {Vec3(0, 0, 0), Vec3(1.00004, 0, 0), Vec3(1.00004, 0, 0), Vec3(2, 0, 0.00003)};
  const std::vector<Vec3> placed = pointsOnGrid(repeated, kGrid);
  ASSERT_EQ(placed.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(placed[k], rounded(repeated[k])) << k;
  EXPECT_TRUE(pointsOnGrid({}, kGrid).empty());
  EXPECT_EQ(pointsOnGrid({Vec3(0.00012, 0, 0)}, kGrid).front(), Vec3(0.0001, 0, 0));
}
