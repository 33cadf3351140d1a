#include "isurface/fitting/cubic_spline.h"

#include <algorithm>
#include <cmath>

namespace isurface {

double PiecewiseCubicCurve::parameterLength() const {
  return segments_.empty() ? 0.0 : segments_.back().start + segments_.back().length;
}

double PiecewiseCubicCurve::arcLength() const {
  // 5-point Gauss-Legendre on [0, h]: exact for |r'| polynomial to degree 9, and |r'| is smooth.
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                              0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                              0.4786286704993665, 0.2369268850561891};
  double total = 0;
  for (const CubicSegment& s : segments_)
    for (int k = 0; k < 5; ++k)
      total += 0.5 * s.length * w[k] * s.derivative(0.5 * s.length * (x[k] + 1.0)).norm();
  return total;
}

std::size_t PiecewiseCubicCurve::segmentAt(double l) const {
  // The last segment whose start is <= l.
  auto it = std::upper_bound(segments_.begin(), segments_.end(), l,
                             [](double value, const CubicSegment& s) { return value < s.start; });
  return it == segments_.begin() ? 0 : static_cast<std::size_t>(it - segments_.begin()) - 1;
}

Vec3 PiecewiseCubicCurve::position(double l) const {
  if (segments_.empty()) return Vec3::Zero();
  l = std::clamp(l, 0.0, parameterLength());
  const CubicSegment& s = segments_[segmentAt(l)];
  return s.position(std::min(l - s.start, s.length));
}

Vec3 PiecewiseCubicCurve::derivative(double l) const {
  if (segments_.empty()) return Vec3::Zero();
  l = std::clamp(l, 0.0, parameterLength());
  const CubicSegment& s = segments_[segmentAt(l)];
  return s.derivative(std::min(l - s.start, s.length));
}

Vec3 PiecewiseCubicCurve::secondDerivative(double l) const {
  if (segments_.empty()) return Vec3::Zero();
  l = std::clamp(l, 0.0, parameterLength());
  const CubicSegment& s = segments_[segmentAt(l)];
  return s.secondDerivative(std::min(l - s.start, s.length));
}

double PiecewiseCubicCurve::curvature(double l) const {
  const Vec3 d1 = derivative(l), d2 = secondDerivative(l);
  const double speed = d1.norm();
  if (speed < kLengthEpsilon) return 0.0;
  return d1.cross(d2).norm() / (speed * speed * speed);
}

namespace {

double distanceToChord(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 < kLengthEpsilon * kLengthEpsilon) return (p - a).norm();
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Largest distance of the segment between u0 and u1 from the chord joining its ends, checked at
// evenly spaced interior points. A cubic's deviation from its chord has at most two extrema; 16
// checks find them closely once the piece is near tolerance.
double chordDeviation(const CubicSegment& s, double u0, double u1) {
  constexpr int kChecks = 16;
  const Vec3 a = s.position(u0), b = s.position(u1);
  double worst = 0;
  for (int k = 1; k < kChecks; ++k)
    worst = std::max(worst, distanceToChord(s.position(u0 + (u1 - u0) * k / kChecks), a, b));
  return worst;
}

void subdivide(const CubicSegment& s, double u0, double u1, double tolerance, int depth,
               std::vector<Vec3>& out) {
  // Depth 30 halves a segment to 1e-9 of its length: far below any tolerance that makes sense.
  if (depth < 30 && chordDeviation(s, u0, u1) > tolerance) {
    const double mid = 0.5 * (u0 + u1);
    subdivide(s, u0, mid, tolerance, depth + 1, out);
    subdivide(s, mid, u1, tolerance, depth + 1, out);
    return;
  }
  out.push_back(s.position(u1));
}

}  // namespace

std::vector<Vec3> PiecewiseCubicCurve::resample(double tolerance) const {
  std::vector<Vec3> out;
  if (segments_.empty()) return out;
  out.push_back(segments_.front().position(0));
  for (const CubicSegment& s : segments_) subdivide(s, 0.0, s.length, tolerance, 0, out);
  return out;
}

void solveTridiagonal(std::vector<double> sub, std::vector<double> diag, std::vector<double> super,
                      std::vector<double>& rhs) {
  const std::size_t n = diag.size();
  if (n == 0) return;
  for (std::size_t i = 1; i < n; ++i) {
    const double factor = sub[i] / diag[i - 1];
    diag[i] -= factor * super[i - 1];
    rhs[i] -= factor * rhs[i - 1];
  }
  rhs[n - 1] /= diag[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) rhs[i] = (rhs[i] - super[i] * rhs[i + 1]) / diag[i];
}

std::vector<Vec3> distinctPoints(const std::vector<Vec3>& points) {
  std::vector<Vec3> out;
  for (const Vec3& p : points)
    if (out.empty() || (p - out.back()).norm() >= kLengthEpsilon) out.push_back(p);
  return out;
}

PiecewiseCubicCurve fitNaturalCubicSpline(const std::vector<Vec3>& input) {
  const std::vector<Vec3> p = distinctPoints(input);
  const std::size_t n = p.size();
  if (n < 2) return {};
  std::vector<double> h(n - 1);
  std::vector<Vec3> m(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = (p[i + 1] - p[i]).norm();
    m[i] = (p[i + 1] - p[i]) / h[i];
  }
  // Second derivatives M_i at the points; M_0 = M_{n-1} = 0 (natural ends), and for the interior
  // h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (m_i - m_{i-1}).
  std::vector<Vec3> second(n, Vec3::Zero());
  if (n >= 3) {
    const std::size_t k = n - 2;
    std::vector<double> sub(k), diag(k), super(k);
    for (std::size_t j = 0; j < k; ++j) {
      sub[j] = h[j];
      diag[j] = 2.0 * (h[j] + h[j + 1]);
      super[j] = h[j + 1];
    }
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> rhs(k);
      for (std::size_t j = 0; j < k; ++j) rhs[j] = 6.0 * (m[j + 1][axis] - m[j][axis]);
      solveTridiagonal(sub, diag, super, rhs);
      for (std::size_t j = 0; j < k; ++j) second[j + 1][axis] = rhs[j];
    }
  }
  std::vector<CubicSegment> segments(n - 1);
  double l = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    CubicSegment& s = segments[i];
    s.start = l;
    s.length = h[i];
    s.a = p[i];
    s.b = m[i] - h[i] * (2.0 * second[i] + second[i + 1]) / 6.0;
    s.c = second[i] / 2.0;
    s.d = (second[i + 1] - second[i]) / (6.0 * h[i]);
    l += h[i];
  }
  return PiecewiseCubicCurve(std::move(segments));
}

}  // namespace isurface
