// PVT interpolation: cubic Hermite node slopes, natural splines by the three-slope and the
// three-moment equations, interpolation nodes and interpolation error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "isurface/base/diagnostic.h"
#include "isurface/sts/sts_interpolation.h"

using namespace isurface;

namespace {
std::vector<SpiralPoint> samples(const std::vector<double>& t, double (*f)(double)) {
  std::vector<SpiralPoint> out;
  for (double x : t) out.push_back({x, 0, f(x)});
  return out;
}

// Second derivative of the Hermite cubic at its start (atEnd false) or end.
double hermiteSecond(double h, double f0, double f1, double v0, double v1, bool atEnd) {
  const double d = (f1 - f0) / h;
  return atEnd ? (-6 * d + 2 * v0 + 4 * v1) / h : (6 * d - 4 * v0 - 2 * v1) / h;
}

std::vector<double> unevenKnots(std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> step(0.05, 1.0);
  std::vector<double> t{0.0};
  for (std::size_t i = 1; i < n; ++i) t.push_back(t.back() + step(gen));
  return t;
}
}  // namespace

TEST(stsInterpolation, HermiteReproducesACubicWithItsSlopes) {
  auto f = [](double t) { return 2 * t * t * t - t * t + 3 * t - 1; };
  auto df = [](double t) { return 6 * t * t - 2 * t + 3; };
  for (double t : {0.3, 0.9, 1.4})
    EXPECT_NEAR(hermiteValue(0.2, 1.5, f(0.2), f(1.5), df(0.2), df(1.5), t), f(t), 1e-13);
}

TEST(stsInterpolation, PvtThreePointSlopesReproduceAQuadratic) {
  const std::vector<double> t = unevenKnots(12, 1);
  const auto nodes = samples(t, [](double x) { return 2 * x * x - 3 * x + 1; });
  const PvtTrack track = buildPvtTrack(nodes, StsInterpolation::Hermite);
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(track.slope[i], 4 * t[i] - 3, 1e-12);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double x = 0.37 * t[i] + 0.63 * t[i + 1];
    EXPECT_NEAR(track.valueAt(x), 2 * x * x - 3 * x + 1, 1e-12);
  }
}

TEST(stsInterpolation, NaturalSplineByHand) {
  // Knots 0, 1, 2 with values 0, 1, 0: M_1 = 6 f[0, 1, 2] / 2 = -3, so the spline is
  // 1.5 t - 0.5 t^3 on [0, 1], with slopes 1.5, 0, -1.5 at the knots.
  const std::vector<double> t{0, 1, 2}, f{0, 1, 0};
  const auto M = naturalSplineMoments(t, f);
  EXPECT_NEAR(M[1], -3, 1e-15);
  for (const auto& m : {naturalSplineSlopesThreeSlope(t, f), naturalSplineSlopesThreeMoment(t, f)}) {
    EXPECT_NEAR(m[0], 1.5, 1e-15);
    EXPECT_NEAR(m[1], 0.0, 1e-15);
    EXPECT_NEAR(m[2], -1.5, 1e-15);
  }
  const PvtTrack track = buildPvtTrack({{0, 0, 0}, {1, 0, 1}, {2, 0, 0}}, StsInterpolation::SplineThreeSlope);
  EXPECT_NEAR(track.valueAt(0.5), 0.6875, 1e-15);
}

TEST(stsInterpolation, SplinesReproduceAStraightLine) {
  const std::vector<double> t = unevenKnots(20, 2);
  const auto nodes = samples(t, [](double x) { return 0.25 * x - 4; });
  for (auto m : {StsInterpolation::SplineThreeSlope, StsInterpolation::SplineThreeMoment}) {
    const PvtTrack track = buildPvtTrack(nodes, m);
    for (double s : track.slope) EXPECT_NEAR(s, 0.25, 1e-12);
    EXPECT_NEAR(track.valueAt(0.5 * (t[3] + t[4])), 0.25 * 0.5 * (t[3] + t[4]) - 4, 1e-12);
  }
}

TEST(stsInterpolation, ThreeSlopeEqualsThreeMomentAndIsContinuousInAcceleration) {
  const std::vector<double> t = unevenKnots(200, 3);
  std::vector<double> f;
  for (double x : t) f.push_back(std::sin(1.7 * x) + 0.1 * x * x);
  const auto a = naturalSplineSlopesThreeSlope(t, f), b = naturalSplineSlopesThreeMoment(t, f);
  const auto M = naturalSplineMoments(t, f);
  for (std::size_t i = 0; i < t.size(); ++i) ASSERT_NEAR(a[i], b[i], 1e-9);
  for (std::size_t k = 1; k + 1 < t.size(); ++k) {
    const double left = hermiteSecond(t[k] - t[k - 1], f[k - 1], f[k], a[k - 1], a[k], true);
    const double right = hermiteSecond(t[k + 1] - t[k], f[k], f[k + 1], a[k], a[k + 1], false);
    ASSERT_NEAR(left, right, 1e-9);
    ASSERT_NEAR(left, M[k], 1e-9);
  }
  EXPECT_NEAR(hermiteSecond(t[1] - t[0], f[0], f[1], a[0], a[1], false), 0.0, 1e-9);
  const std::size_t n = t.size() - 1;
  EXPECT_NEAR(hermiteSecond(t[n] - t[n - 1], f[n - 1], f[n], a[n - 1], a[n], true), 0.0, 1e-9);
}

TEST(stsInterpolation, UniformAndNonUniformNodes) {
  SpiralParameters p;
  p.workpieceRadius = 10;
  const auto u = uniformNodeAngles(p, 5);
  ASSERT_EQ(u.size(), 5u);
  EXPECT_NEAR(u[1], p.endAngle() / 4, 1e-12);
  EXPECT_EQ(u.back(), p.endAngle());
  EXPECT_THROW(uniformNodeAngles(p, 1), InputError);

  const SinusoidalArraySurface s;
  const auto ccps = discretiseSpiral(s, p, StsDiscretisation::EqualHeight);
  const NonUniformNodes none = nonUniformNodeAngles(s, p, ccps, 1e9);
  EXPECT_EQ(none.theta.size(), ccps.size());
  EXPECT_EQ(none.inserted, 0u);
  // A threshold far below every curvature splits every segment into maxInserted + 1.
  const NonUniformNodes all = nonUniformNodeAngles(s, p, ccps, 1e-12, 2);
  EXPECT_EQ(all.theta.size(), ccps.size() + 2 * (ccps.size() - 1));
  const NonUniformNodes automatic = nonUniformNodeAngles(s, p, ccps, 0);
  EXPECT_GT(automatic.rhoMax, 0);
  EXPECT_GT(automatic.inserted, 0u);
  for (std::size_t i = 1; i < automatic.theta.size(); ++i)
    ASSERT_GT(automatic.theta[i], automatic.theta[i - 1]);
}

TEST(stsInterpolation, InterpolationErrorVanishesOnALinearPath) {
  SpiralParameters p;
  p.toolRadius = 0;
  const ExpressionSurface cone("sqrt(x^2 + y^2)");  // z = r, linear in theta
  const auto nodes = cuttingLocationPointsAt(cone, p, uniformNodeAngles(p, 50));
  for (auto m : {StsInterpolation::Hermite, StsInterpolation::SplineThreeSlope})
    EXPECT_LT(interpolationError(cone, p, buildPvtTrack(nodes, m)).max, 1e-12);
}

TEST(stsInterpolation, HermiteErrorShrinksLikeTheCubeOfTheStep) {
  SpiralParameters p;
  p.workpieceRadius = 10;
  const SinusoidalArraySurface s;
  auto error = [&](std::size_t n) {
    const auto nodes = cuttingLocationPointsAt(s, p, uniformNodeAngles(p, n));
    return interpolationError(s, p, buildPvtTrack(nodes, StsInterpolation::Hermite)).interiorMax;
  };
  const double ratio = error(2000) / error(4000);
  EXPECT_GT(ratio, 6.0);
  EXPECT_LT(ratio, 17.0);
}
