// Spiral discretisation of cutting contact points, tool nose compensation and discrete error.
#include <gtest/gtest.h>

#include <cmath>

#include "isurface/base/diagnostic.h"
#include "isurface/base/units.h"
#include "isurface/sts/sts_spiral.h"

using namespace isurface;

namespace {

SpiralParameters smallSpiral() {
  SpiralParameters p;
  p.workpieceRadius = 20;
  p.feedPerRev = 0.5;
  p.angleStep = 5 * kPi / 180;
  p.arcStep = 1;
  p.heightStep = 0.3;
  p.toolRadius = 0;
  return p;
}
}  // namespace

TEST(stsSpiral, EquationOne) {
  const SpiralParameters p = smallSpiral();
  EXPECT_NEAR(p.endAngle(), 80 * kPi, 1e-12);  // 40 revolutions
  EXPECT_NEAR(p.radiusAt(2 * kPi), 19.5, 1e-12);
  EXPECT_EQ(p.radiusAt(100 * kPi), 0.0);
  const ExpressionSurface tilted("0.1 * x");
  const SpiralPoint q = spiralContactPoint(tilted, p, kPi / 3);
  EXPECT_NEAR(q.r, 20 - 0.5 / 6, 1e-12);
  EXPECT_NEAR(q.z, 0.1 * q.r * 0.5, 1e-12);
}

TEST(stsSpiral, EqualAngleSteps) {
  const SpiralParameters p = smallSpiral();
  const auto points = discretiseSpiral(ExpressionSurface("0"), p, StsDiscretisation::EqualAngle);
  const std::size_t steps = static_cast<std::size_t>(std::ceil(p.endAngle() / p.angleStep));
  ASSERT_EQ(points.size(), steps + 1);
  EXPECT_NEAR(points[7].theta, 7 * p.angleStep, 1e-12);
  EXPECT_NEAR(points[7].r, 20 - 0.5 * 7 * p.angleStep / (2 * kPi), 1e-12);
  EXPECT_EQ(points.back().theta, p.endAngle());
  EXPECT_EQ(points.back().r, 0.0);
}

TEST(stsSpiral, EqualArcLengthSteps) {
  const SpiralParameters p = smallSpiral();
  const auto points = discretiseSpiral(ExpressionSurface("0"), p, StsDiscretisation::EqualArcLength);
  const double b = 0.5 / (2 * kPi);
  EXPECT_NEAR(points[1].theta, 1 / std::sqrt(400 + b * b), 1e-15);
  const double r1 = points[1].r;
  EXPECT_NEAR(points[2].theta - points[1].theta, 1 / std::sqrt(r1 * r1 + b * b), 1e-15);
  EXPECT_EQ(points.back().theta, p.endAngle());
}

TEST(stsSpiral, EqualHeightHalvesTheAngleUntilTheHeightIsAllowed) {
  const SpiralParameters p = smallSpiral();  // Delta Z_m = 0.3 mm
  // z = y: from the entry point (20, 0, 0) the arc step gives dz ~ 1.0, half of it ~ 0.5, a
  // quarter ~ 0.25 <= 0.3: the second CCP is a quarter of the arc step on.
  const auto points = discretiseSpiral(ExpressionSurface("y"), p, StsDiscretisation::EqualHeight);
  const double arcStep = 1 / p.arcRate(0);
  EXPECT_NEAR(points[1].theta, arcStep / 4, 1e-15);
  for (std::size_t i = 1; i < points.size(); ++i)
    ASSERT_LE(std::abs(points[i].z - points[i - 1].z), p.heightStep + 1e-12);
}

TEST(stsSpiral, EqualHeightFallsBackToTheAngleStep) {
  SpiralParameters p = smallSpiral();
  p.arcStep = 5;  // 5 mm at r = 20 is 0.25 rad, more than the 5 degree allowable angle
  const auto points = discretiseSpiral(ExpressionSurface("0"), p, StsDiscretisation::EqualHeight);
  EXPECT_NEAR(points[1].theta, p.angleStep, 1e-15);
}

TEST(stsSpiral, EqualHeightBoundsTheStepOnThePaperSinusoid) {
  SpiralParameters p;
  p.workpieceRadius = 30;
  p.heightStep = 0.1;
  p.angleStep = 3 * kPi / 180;
  const SinusoidalArraySurface s;
  const auto points = discretiseSpiral(s, p, StsDiscretisation::EqualHeight);
  for (std::size_t i = 1; i < points.size(); ++i) {
    ASSERT_GT(points[i].theta, points[i - 1].theta);
    ASSERT_LE(std::abs(points[i].z - points[i - 1].z), p.heightStep + 1e-12);
  }
}

TEST(stsSpiral, NoseCompensationOfAPlane) {
  const ExpressionSurface plane("1 + 0.3 * x");
  const double rt = 0.5;
  // Radial slope 0.3 at theta = 0: lift R_t (sqrt(1 + s^2) - 1); contact R_t s / sqrt(1 + s^2) out.
  const NoseCompensation c = compensateNoseRadius(plane, 10, 0, rt);
  EXPECT_NEAR(c.z, 1 + 3 + rt * (std::sqrt(1.09) - 1), 1e-12);
  // The expression's slope comes from central differences, good to ~1e-10.
  EXPECT_NEAR(c.contactOffset, rt * 0.3 / std::sqrt(1.09), 1e-9);
  // At theta = 90 degrees the radial section is level: no lift.
  EXPECT_NEAR(compensateNoseRadius(plane, 10, kPi / 2, rt).z, 1.0, 1e-12);
}

TEST(stsSpiral, NoseCompensationOfASphere) {
  const double rs = 50, rt = 0.5, r = 10;
  const ExpressionSurface bowl("50 - sqrt(2500 - x^2 - y^2)");
  // The nose centre rides on the sphere of radius Rs - Rt about the bowl's centre (0, Rs).
  const NoseCompensation c = compensateNoseRadius(bowl, r, 0.7, rt);
  EXPECT_NEAR(c.z, rs - std::sqrt((rs - rt) * (rs - rt) - r * r) - rt, 1e-10);
  EXPECT_NEAR(c.contactOffset, r * rt / (rs - rt), 1e-9);
}

TEST(stsSpiral, DiscreteErrorOfOneChordOnAParaboloid) {
  SpiralParameters p;
  p.workpieceRadius = 1;
  p.feedPerRev = 1;
  p.angleStep = 7;  // more than the whole path (2 pi): two CCPs, at the rim and the centre
  const ExpressionSurface paraboloid("x^2 + y^2");
  const auto points = discretiseSpiral(paraboloid, p, StsDiscretisation::EqualAngle);
  ASSERT_EQ(points.size(), 2u);
  // Along the spiral z = u^2 with u = 1 - theta / 2 pi; the spline through two points is the
  // chord z = u: the error u - u^2 is 1/4 in the middle, 20/81 at u = 5/9.
  EXPECT_NEAR(discreteError(paraboloid, p, points, 1).max, 0.25, 1e-15);
  const ErrorProfile e = discreteError(paraboloid, p, points, 8);
  EXPECT_NEAR(e.max, 20.0 / 81, 1e-15);
  ASSERT_EQ(e.perSegment.size(), 1u);
}

TEST(stsSpiral, DiscreteErrorVanishesWhereTheSplineIsExact) {
  // z = r is linear in theta along the spiral.
  const auto p = smallSpiral();
  const ExpressionSurface cone("sqrt(x^2 + y^2)");
  const auto points = discretiseSpiral(cone, p, StsDiscretisation::EqualArcLength);
  EXPECT_LT(discreteError(cone, p, points).max, 1e-12);
}

TEST(stsSpiral, ImpossibleParametersAreInputErrors) {
  SpiralParameters p = smallSpiral();
  p.feedPerRev = 0;
  EXPECT_THROW(p.validate(), InputError);
  p = smallSpiral();
  p.heightStep = -1;
  EXPECT_THROW(discretiseSpiral(ExpressionSurface("0"), p, StsDiscretisation::EqualHeight), InputError);
  EXPECT_THROW(parseStsDiscretisation("spiral"), InputError);
}
