#include "isurface/sts/sts_surface.h"

#include <fmt/format.h>
#include "isurface/base/units.h"

#include <cmath>
#include <muParser.h>

#include "isurface/base/diagnostic.h"

namespace isurface {

namespace {
// Central-difference steps, mm: small enough for a 1e-8 relative derivative error on surfaces
// whose features are millimetres wide, large enough that rounding stays below that.
constexpr double kGradientStep = 1e-5;
constexpr double kHessianStep = 1e-4;
}  // namespace

Eigen::Vector2d StsSurface::gradient(double x, double y) const {
  const double h = kGradientStep;
  return {(height(x + h, y) - height(x - h, y)) / (2 * h),
          (height(x, y + h) - height(x, y - h)) / (2 * h)};
}

Eigen::Matrix2d StsSurface::hessian(double x, double y) const {
  const double h = kHessianStep;
  const Eigen::Vector2d dx = (gradient(x + h, y) - gradient(x - h, y)) / (2 * h);
  const Eigen::Vector2d dy = (gradient(x, y + h) - gradient(x, y - h)) / (2 * h);
  Eigen::Matrix2d H;
  const double fxy = 0.5 * (dx.y() + dy.x());
  H << dx.x(), fxy, fxy, dy.y();
  return H;
}

SurfaceCurvature StsSurface::curvature(double x, double y) const {
  const Eigen::Vector2d g = gradient(x, y);
  const Eigen::Matrix2d H = hessian(x, y);
  const double p = g.x(), q = g.y();
  const double w = 1 + p * p + q * q;
  SurfaceCurvature c;
  c.gaussian = (H(0, 0) * H(1, 1) - H(0, 1) * H(0, 1)) / (w * w);
  c.mean = ((1 + q * q) * H(0, 0) - 2 * p * q * H(0, 1) + (1 + p * p) * H(1, 1)) /
           (2 * std::pow(w, 1.5));
  const double disc = std::sqrt(std::max(0.0, c.mean * c.mean - c.gaussian));
  c.k1 = c.mean + disc;
  c.k2 = c.mean - disc;
  return c;
}

ToricSurface::ToricSurface(double orthogonalArcRadius, double basicArcRadius)
    : R_(orthogonalArcRadius), a_(basicArcRadius) {
  if (!(R_ > 0) || !(a_ > 0))
    throw InputError({"sts", 0, 0, "toric surface: radii R and a must be positive (mm)"});
}

double ToricSurface::height(double x, double y) const {
  const double s = std::sqrt(std::max(0.0, a_ * a_ - y * y));
  const double w = R_ + s;
  return R_ + a_ - std::sqrt(std::max(0.0, w * w - x * x));
}

Eigen::Vector2d ToricSurface::gradient(double x, double y) const {
  const double s = std::sqrt(std::max(1e-300, a_ * a_ - y * y));
  const double w = R_ + s;
  const double q = std::sqrt(std::max(1e-300, w * w - x * x));
  // dz/dx = x / q; dz/dy = -(w dw/dy) / q with dw/dy = -y / s.
  return {x / q, w * y / (s * q)};
}

SinusoidalArraySurface::SinusoidalArraySurface(double amplitude, double wavelength)
    : A_(amplitude), k_(0) {
  if (!(wavelength > 0))
    throw InputError({"sts", 0, 0, "sinusoidal surface: the wavelength must be positive (mm)"});
  k_ = 2 * kPi / wavelength;
}

double SinusoidalArraySurface::height(double x, double y) const {
  return A_ * std::sin(k_ * x) * std::sin(k_ * y);
}

Eigen::Vector2d SinusoidalArraySurface::gradient(double x, double y) const {
  return {A_ * k_ * std::cos(k_ * x) * std::sin(k_ * y),
          A_ * k_ * std::sin(k_ * x) * std::cos(k_ * y)};
}

Eigen::Matrix2d SinusoidalArraySurface::hessian(double x, double y) const {
  const double kk = A_ * k_ * k_;
  Eigen::Matrix2d H;
  const double fxy = kk * std::cos(k_ * x) * std::cos(k_ * y);
  const double fxx = -kk * std::sin(k_ * x) * std::sin(k_ * y);
  H << fxx, fxy, fxy, fxx;
  return H;
}

// muParser reads the variables through pointers, so they live beside the parser.
struct ExpressionSurface::Parser {
  mu::Parser parser;
  double x = 0, y = 0;
};

namespace {

constexpr std::size_t kLongestExpression = 10000;  // characters
constexpr int kDeepestNesting = 64;                 // parentheses

// muParser also reads assignments ("x=1" sets x and evaluates to 1: a flat surface) and runs
// out of stack on deep nesting; neither is a surface z = f(x, y).
void checkExpressionShape(const std::string& expression) {
  const auto refuse = [&](const std::string& why) {
    throw InputError({"sts", 0, 0, "surface expression '" + expression.substr(0, 80) +
                                       (expression.size() > 80 ? "...'" : "'") + ": " + why});
  };
  if (expression.size() > kLongestExpression)
    refuse(fmt::format("{} characters, more than {}", expression.size(), kLongestExpression));
  int depth = 0;
  for (std::size_t i = 0; i < expression.size(); ++i) {
    const char c = expression[i];
    if (c == '(' && ++depth > kDeepestNesting) refuse(fmt::format("nested deeper than {} parentheses", kDeepestNesting));
    if (c == ')') --depth;
    if (c != '=') continue;
    if (i + 1 < expression.size() && expression[i + 1] == '=') {
      ++i;  // ==
      continue;
    }
    if (i > 0 && (expression[i - 1] == '<' || expression[i - 1] == '>' || expression[i - 1] == '!')) continue;
    refuse(fmt::format("'=' at character {} assigns: give only the height, f(x, y) for z = f(x, y), in mm", i + 1));
  }
}

}  // namespace

ExpressionSurface::ExpressionSurface(const std::string& expression)
    : expression_(expression), parser_(std::make_unique<Parser>()) {
  checkExpressionShape(expression);
  try {
    parser_->parser.DefineVar("x", &parser_->x);
    parser_->parser.DefineVar("y", &parser_->y);
    parser_->parser.SetExpr(expression);
    parser_->parser.Eval();  // parses now, so a bad expression fails here and not mid-path
  } catch (const mu::Parser::exception_type& e) {
    throw InputError({"sts", 0, 0,
                      "surface expression '" + expression + "': " + e.GetMsg() +
                          " (use the variables x and y, in mm)"});
  }
}

ExpressionSurface::~ExpressionSurface() = default;

double ExpressionSurface::height(double x, double y) const {
  parser_->x = x;
  parser_->y = y;
  try {
    return parser_->parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw InputError({"sts", 0, 0, "surface expression '" + expression_ + "': " + e.GetMsg()});
  }
}

std::unique_ptr<StsSurface> makeStsSurface(const std::string& spec) {
  if (spec == "toric") return std::make_unique<ToricSurface>();
  if (spec == "sinusoid") return std::make_unique<SinusoidalArraySurface>();
  if (spec.empty()) throw InputError({"sts", 0, 0, "--surface: empty surface expression"});
  return std::make_unique<ExpressionSurface>(spec);
}

}  // namespace isurface
