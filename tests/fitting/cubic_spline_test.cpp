// Natural cubic spline in the chord-length parameter, and the tridiagonal solver.
#include "isurface/fitting/cubic_spline.h"

#include <gtest/gtest.h>

#include <cmath>

namespace isurface {
namespace {

TEST(cubicSpline, thomasSolvesAKnownSystem) {
  // [2 1 0; 1 2 1; 0 1 2] x = [4 8 8] -> x = [1 2 3].
  std::vector<double> rhs = {4, 8, 8};
  solveTridiagonal({0, 1, 1}, {2, 2, 2}, {1, 1, 0}, rhs);
  EXPECT_NEAR(rhs[0], 1, 1e-14);
  EXPECT_NEAR(rhs[1], 2, 1e-14);
  EXPECT_NEAR(rhs[2], 3, 1e-14);
}

TEST(cubicSpline, interpolatesWithNaturalEnds) {
  std::vector<Vec3> p;
  for (int i = 0; i < 9; ++i) p.push_back(Vec3(i * 1.3, std::sin(i * 0.7) * 2, 0.2 * i * i));
  const PiecewiseCubicCurve c = fitNaturalCubicSpline(p);
  ASSERT_EQ(c.segments().size(), p.size() - 1);
  double l = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (i > 0) l += (p[i] - p[i - 1]).norm();
    EXPECT_LE((c.position(l) - p[i]).norm(), 1e-12) << i;
  }
  EXPECT_LE(c.secondDerivative(0).norm(), 1e-12);
  EXPECT_LE(c.secondDerivative(c.parameterLength()).norm(), 1e-12);
  // C2 at the joints.
  const auto& s = c.segments();
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    EXPECT_LE((s[i].derivative(s[i].length) - s[i + 1].derivative(0)).norm(), 1e-9);
    EXPECT_LE((s[i].secondDerivative(s[i].length) - s[i + 1].secondDerivative(0)).norm(), 1e-9);
  }
}

TEST(cubicSpline, knownThreePointCase) {
  // Points (0,0), (1,1), (2,0): chords h = sqrt 2 each, slopes m0 = (1,1)/sqrt2, m1 = (1,-1)/sqrt2.
  // One interior equation: 2 (h + h) M1 = 6 (m1 - m0) -> M1 = 6 (0, -sqrt2) / (4 sqrt2) = (0, -1.5).
  // Segment 0: B = m0 - h (2 M0 + M1) / 6 = (1/sqrt2, 1/sqrt2 + sqrt2 * 1.5 / 6).
  const PiecewiseCubicCurve c = fitNaturalCubicSpline({Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(2, 0, 0)});
  const double h = std::sqrt(2.0);
  EXPECT_LE((c.secondDerivative(h) - Vec3(0, -1.5, 0)).norm(), 1e-12);
  EXPECT_LE((c.derivative(0) - Vec3(1 / h, 1 / h + h * 1.5 / 6, 0)).norm(), 1e-12);
  EXPECT_NEAR(c.derivative(h).y(), 0.0, 1e-12);  // symmetric: flat at the apex
}

TEST(cubicSpline, degenerateInputs) {
  EXPECT_TRUE(fitNaturalCubicSpline({}).empty());
  EXPECT_TRUE(fitNaturalCubicSpline({Vec3(1, 2, 3), Vec3(1, 2, 3)}).empty());
  const PiecewiseCubicCurve line = fitNaturalCubicSpline({Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 2)});
  ASSERT_EQ(line.segments().size(), 1u);
  EXPECT_LE((line.position(1) - Vec3(0, 0, 1)).norm(), 1e-12);
  EXPECT_EQ(line.curvature(1), 0.0);
  // Evaluation outside the parameter range clamps to the ends.
  EXPECT_LE((line.position(-5) - Vec3(0, 0, 0)).norm(), 1e-12);
  EXPECT_LE((line.position(9) - Vec3(0, 0, 2)).norm(), 1e-12);
}

}  // namespace
}  // namespace isurface
