#pragma once
// Surfaces z = f(x, y) (all lengths in mm) for slow tool servo (STS) turning tool paths:
// the toric surface and the sinusoidal array surface of the STS tool path paper (its equations
// 10 and 11 with the parameters of its Tables 1 and 2), and user expressions parsed at run time.
#include <memory>
#include <string>

#include <Eigen/Core>

namespace isurface {

// Curvatures of the graph z = f(x, y) at one point, mm^-1. Signs follow the +z normal:
// a bowl opening upwards (z = r^2 / 2R) has positive curvatures 1/R.
struct SurfaceCurvature {
  double mean = 0;
  double gaussian = 0;
  double k1 = 0;  // larger principal curvature
  double k2 = 0;  // smaller principal curvature
};

class StsSurface {
 public:
  virtual ~StsSurface() = default;
  virtual std::string name() const = 0;
  virtual double height(double x, double y) const = 0;  // mm
  // (dz/dx, dz/dy), dimensionless. Default: central differences of height().
  virtual Eigen::Vector2d gradient(double x, double y) const;
  // [[fxx, fxy], [fxy, fyy]], mm^-1. Default: central differences of gradient().
  virtual Eigen::Matrix2d hessian(double x, double y) const;
  SurfaceCurvature curvature(double x, double y) const;
};

// Equation 10: z = R + a - sqrt((R + sqrt(a^2 - y^2))^2 - x^2). Table 1: R = 140, a = 100.
// Defined for |y| <= a and |x| <= R + sqrt(a^2 - y^2). Vertex at the origin, z(0, 0) = 0.
class ToricSurface final : public StsSurface {
 public:
  explicit ToricSurface(double orthogonalArcRadius = 140.0, double basicArcRadius = 100.0);
  std::string name() const override { return "toric"; }
  double height(double x, double y) const override;
  Eigen::Vector2d gradient(double x, double y) const override;

 private:
  double R_, a_;
};

// Equation 11: z = A sin(2 pi x / w) sin(2 pi y / w). Table 2: A = 1 mm, w = 30 mm.
class SinusoidalArraySurface final : public StsSurface {
 public:
  explicit SinusoidalArraySurface(double amplitude = 1.0, double wavelength = 30.0);
  std::string name() const override { return "sinusoid"; }
  double height(double x, double y) const override;
  Eigen::Vector2d gradient(double x, double y) const override;
  Eigen::Matrix2d hessian(double x, double y) const override;

 private:
  double A_, k_;  // k = 2 pi / w, mm^-1
};

// z = expression in x and y (mm), e.g. "0.01*(x^2+y^2)" or "sin(x/5)*cos(y/5)", parsed by
// muParser (functions sin, cos, tan, sqrt, exp, log, abs, ... ; constants _pi, _e).
// Throws InputError for a malformed expression or one that uses other variables.
class ExpressionSurface final : public StsSurface {
 public:
  explicit ExpressionSurface(const std::string& expression);
  ~ExpressionSurface() override;
  std::string name() const override { return expression_; }
  double height(double x, double y) const override;

 private:
  struct Parser;
  std::string expression_;
  std::unique_ptr<Parser> parser_;
};

// "toric" and "sinusoid" (paper parameters), anything else is an expression.
std::unique_ptr<StsSurface> makeStsSurface(const std::string& spec);

}  // namespace isurface
