// Surfaces for slow tool servo tool paths: the paper's toric and sinusoidal array surfaces and
// user expressions, with their gradients and curvatures.
#include <gtest/gtest.h>

#include <cmath>

#include "isurface/base/diagnostic.h"
#include "isurface/base/units.h"
#include "isurface/sts/sts_surface.h"

using namespace isurface;

namespace {

// The base class's central differences, to check analytic overrides against.
class NumericCopy final : public StsSurface {
 public:
  explicit NumericCopy(const StsSurface& s) : s_(s) {}
  std::string name() const override { return "numeric"; }
  double height(double x, double y) const override { return s_.height(x, y); }

 private:
  const StsSurface& s_;
};
}  // namespace

TEST(stsSurface, ToricMatchesItsTwoArcsAlongTheAxes) {
  const ToricSurface toric(140, 100);
  EXPECT_NEAR(toric.height(0, 0), 0.0, 1e-12);
  // Along x the section is a circle of radius R + a = 240 mm, along y one of radius a = 100 mm.
  EXPECT_NEAR(toric.height(12, 0), 240 - std::sqrt(240.0 * 240 - 144), 1e-12);
  EXPECT_NEAR(toric.height(0, 12), 100 - std::sqrt(100.0 * 100 - 144), 1e-12);
  const SurfaceCurvature c = toric.curvature(0, 0);
  EXPECT_NEAR(c.k1, 1.0 / 100, 1e-6);
  EXPECT_NEAR(c.k2, 1.0 / 240, 1e-6);
}

TEST(stsSurface, AnalyticGradientsAgreeWithDifferences) {
  const ToricSurface toric;
  const SinusoidalArraySurface sinusoid;
  for (const StsSurface* s : {static_cast<const StsSurface*>(&toric), static_cast<const StsSurface*>(&sinusoid)}) {
    const NumericCopy numeric(*s);
    for (auto [x, y] : {std::pair{3.0, -7.0}, std::pair{-15.5, 11.2}, std::pair{18.0, 4.0}}) {
      EXPECT_NEAR((s->gradient(x, y) - numeric.gradient(x, y)).norm(), 0.0, 1e-8) << s->name();
      EXPECT_NEAR((s->hessian(x, y) - numeric.hessian(x, y)).norm(), 0.0, 1e-5) << s->name();
    }
  }
}

TEST(stsSurface, SinusoidPeakHasAmplitudeAndCurvature) {
  const SinusoidalArraySurface s(1.0, 30.0);
  const double k = 2 * kPi / 30;
  EXPECT_NEAR(s.height(7.5, 7.5), 1.0, 1e-15);
  EXPECT_NEAR(s.gradient(7.5, 7.5).norm(), 0.0, 1e-15);
  const SurfaceCurvature c = s.curvature(7.5, 7.5);  // a cap: both curvatures -A k^2
  EXPECT_NEAR(c.k1, -k * k, 1e-12);
  EXPECT_NEAR(c.k2, -k * k, 1e-12);
  EXPECT_NEAR(c.gaussian, k * k * k * k, 1e-12);
}

TEST(stsSurface, ExpressionBowl) {
  const ExpressionSurface bowl("(x^2 + y^2) / 20");  // paraboloid, vertex radius 10 mm
  EXPECT_DOUBLE_EQ(bowl.height(2, 4), 1.0);
  EXPECT_NEAR(bowl.gradient(1, 2).x(), 0.1, 1e-9);
  EXPECT_NEAR(bowl.gradient(1, 2).y(), 0.2, 1e-9);
  const SurfaceCurvature c = bowl.curvature(0, 0);
  EXPECT_NEAR(c.mean, 0.1, 1e-6);
  EXPECT_NEAR(c.gaussian, 0.01, 1e-6);
}

TEST(stsSurface, BadExpressionsAreInputErrors) {
  EXPECT_THROW(ExpressionSurface("x +"), InputError);
  EXPECT_THROW(ExpressionSurface("x + z"), InputError);
  EXPECT_THROW(makeStsSurface(""), InputError);
}

TEST(stsSurface, FactoryNames) {
  EXPECT_EQ(makeStsSurface("toric")->name(), "toric");
  EXPECT_EQ(makeStsSurface("sinusoid")->name(), "sinusoid");
  EXPECT_EQ(makeStsSurface("sin(x)*y")->name(), "sin(x)*y");
}

TEST(stsSurface, AnAssignmentIsNotASurface) {
  // muParser reads "x=1" as setting x: every height would be 1, a flat surface without a word.
  for (const std::string bad : {"x=1", "y = x*2", "x+=1", "z=sin(x)"}) {
    try {
      makeStsSurface(bad);
      ADD_FAILURE() << bad << " was taken for a surface";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("'='"), std::string::npos) << e.what();
    }
  }
  for (const std::string good : {"x==1", "x<=1 ? 0 : 1", "(x>=0) * 0.1", "x!=0"}) EXPECT_NO_THROW(makeStsSurface(good)) << good;
}

TEST(stsSurface, DeepNestingIsRefusedUpFront) {
  const std::string deep = std::string(5000, '(') + "x" + std::string(5000, ')');
  EXPECT_THROW(makeStsSurface(deep), InputError);
  EXPECT_THROW(makeStsSurface("x+" + std::string(20000, '1')), InputError);
}
