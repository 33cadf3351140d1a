#include "chord_spline.h"

#include <algorithm>
#include <cmath>

namespace isurface {

namespace {

// Gauss-Legendre nodes and weights on [0, 1], three points: exact for the length of a quintic
// piece this close to straight to well below a nanometre per span.
constexpr double kNodes[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
constexpr double kWeights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
// Samples per piece where its curvature, deviation and directions are looked at.
constexpr int kLooks = 32;

}  // namespace

ChordKnot ChordKnot::straight(const Vec3& from, const Vec3& to) {
  ChordKnot k;
  const Vec3 d = to - from;
  if (d.norm() > 0) k.tangent = d.normalized();
  return k;
}

ChordKnot ChordKnot::through(const Vec3& previous, const Vec3& point, const Vec3& next) {
  const Vec3 u = previous - point, w = next - point;
  const Vec3 normal = u.cross(w);
  const double lengths = u.norm() * w.norm() * (next - previous).norm();
  if (!(normal.norm() > kCollinearRelative * lengths) || lengths == 0) return straight(previous, next);
  // The circumcentre relative to `point`.
  const Vec3 centre = (u.squaredNorm() * w - w.squaredNorm() * u).cross(normal) / (2.0 * normal.squaredNorm());
  ChordKnot k;
  k.curvature = centre / centre.squaredNorm();
  const Vec3 inward = centre.normalized();
  const Vec3 along = next - previous;
  k.tangent = (along - along.dot(inward) * inward).normalized();
  return k;
}

ChordSpline::ChordSpline(const Vec3& start, const ChordKnot& startKnot, const Vec3& end, const ChordKnot& endKnot) {
  // Quintic Hermite in u in [0, 1]: p(0), p'(0) = L T0, p''(0) = L^2 K0 and the same at u = 1.
  // With p'' normal to p' at the ends, the curvature there is |K| exactly; L, the length of the
  // circular arc over the chord that turns as the end tangents do, makes the parameter's speed
  // nearly even, and an arc of a circle nearly exact (its error falls with the sixth power of
  // the turn).
  const double chord = (end - start).norm();
  const double halfTurn = 0.5 * std::acos(std::clamp(startKnot.tangent.dot(endKnot.tangent), -1.0, 1.0));
  const double h = halfTurn > 1e-6 && halfTurn < 1.5 ? chord * halfTurn / std::sin(halfTurn) : chord;
  const Vec3 p0 = start, p1 = end;
  const Vec3 d0 = h * startKnot.tangent, d1 = h * endKnot.tangent;
  const Vec3 a0 = h * h * startKnot.curvature, a1 = h * h * endKnot.curvature;
  c_[0] = p0;
  c_[1] = d0;
  c_[2] = 0.5 * a0;
  c_[3] = -10.0 * p0 - 6.0 * d0 - 1.5 * a0 + 0.5 * a1 - 4.0 * d1 + 10.0 * p1;
  c_[4] = 15.0 * p0 + 8.0 * d0 + 1.5 * a0 - a1 + 7.0 * d1 - 15.0 * p1;
  c_[5] = -6.0 * p0 - 3.0 * d0 - 0.5 * a0 + 0.5 * a1 - 3.0 * d1 + 6.0 * p1;

  cumulative_[0] = 0;
  for (int i = 0; i <= kSpans; ++i) {
    const double speed = derivative(static_cast<double>(i) / kSpans).norm();
    slope_[i] = speed > 0 ? 1.0 / speed : 0.0;
    if (i == kSpans) break;
    double span = 0;
    for (int g = 0; g < 3; ++g) span += kWeights[g] * derivative((i + kNodes[g]) / kSpans).norm();
    cumulative_[i + 1] = cumulative_[i] + span / kSpans;
  }
}

ChordSpline::Shape ChordSpline::shape() const {
  Shape out;
  const Vec3 along = end() - start();
  for (int i = 0; i <= kLooks; ++i) {
    const double u = static_cast<double>(i) / kLooks;
    const Vec3 d = derivative(u);
    const double speed = d.norm();
    if (!(d.dot(along) >= 0.5 * along.squaredNorm())) out.wellFormed = false;
    if (speed > 0) {
      out.largestCurvature = std::max(out.largestCurvature, d.cross(secondDerivative(u)).norm() / (speed * speed * speed));
      out.largestDirection = out.largestDirection.cwiseMax(d.cwiseAbs() / speed);
    }
  }
  return out;
}

Vec3 ChordSpline::point(double u) const {
  return c_[0] + u * (c_[1] + u * (c_[2] + u * (c_[3] + u * (c_[4] + u * c_[5]))));
}

Vec3 ChordSpline::derivative(double u) const {
  return c_[1] + u * (2.0 * c_[2] + u * (3.0 * c_[3] + u * (4.0 * c_[4] + u * 5.0 * c_[5])));
}

Vec3 ChordSpline::secondDerivative(double u) const {
  return 2.0 * c_[2] + u * (6.0 * c_[3] + u * (12.0 * c_[4] + u * 20.0 * c_[5]));
}

// The parameter at arc length s: the table's span, then the cubic through its nodes.
double ChordSpline::parameterAt(double s) const {
  if (s <= 0) return 0.0;
  if (s >= length()) return 1.0;
  const auto above = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  const int span = std::min(kSpans - 1, static_cast<int>(above - cumulative_.begin()) - 1);
  const double s0 = cumulative_[span], w = cumulative_[span + 1] - s0;
  const double u0 = static_cast<double>(span) / kSpans, u1 = static_cast<double>(span + 1) / kSpans;
  if (!(w > 0)) return u0;
  const double t = (s - s0) / w, t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * u0 + (t3 - 2 * t2 + t) * w * slope_[span] + (3 * t2 - 2 * t3) * u1 +
         (t3 - t2) * w * slope_[span + 1];
}

double ChordSpline::farthestFrom(const Vec3& a, const Vec3& b) const {
  double farthest = 0;
  for (int i = 0; i <= kLooks; ++i) farthest = std::max(farthest, distanceToSegment(point(static_cast<double>(i) / kLooks), a, b));
  return farthest;
}

Vec3 ChordSpline::at(double s) const { return point(parameterAt(s)); }

Vec3 ChordSpline::tangentAt(double s) const {
  const Vec3 d = derivative(parameterAt(s));
  return d.norm() > 0 ? Vec3(d.normalized()) : Vec3((end() - start()).normalized());
}

}  // namespace isurface
