#pragma once
// Piecewise cubic curves in 3D parameterised by accumulated chord length l (mm), the form both
// the Akima spline (akima_spline.h) and the natural cubic spline below take:
//   r(l) = A + B u + C u^2 + D u^3,  u = l - l_i in [0, h_i],  h_i = |P_{i+1} - P_i|.
// Chord length stands in for arc length (the paper's equation 2), so |r'(l)| is near but not
// exactly 1; curvature is therefore computed with the general formula.
#include <vector>

#include "isurface/base/geometry.h"

namespace isurface {

struct CubicSegment {
  double start = 0;   // l_i, mm
  double length = 0;  // h_i, mm (chord)
  Vec3 a = Vec3::Zero(), b = Vec3::Zero(), c = Vec3::Zero(), d = Vec3::Zero();

  Vec3 position(double u) const { return a + u * (b + u * (c + u * d)); }
  Vec3 derivative(double u) const { return b + u * (2.0 * c + 3.0 * u * d); }
  Vec3 secondDerivative(double u) const { return 2.0 * c + 6.0 * u * d; }
  Vec3 endPoint() const { return position(length); }
};

class PiecewiseCubicCurve {
 public:
  PiecewiseCubicCurve() = default;
  explicit PiecewiseCubicCurve(std::vector<CubicSegment> segments) : segments_(std::move(segments)) {}

  const std::vector<CubicSegment>& segments() const { return segments_; }
  bool empty() const { return segments_.empty(); }
  // Total parameter length: the sum of the chords, mm.
  double parameterLength() const;
  // True length of the curve, mm (Gauss-Legendre quadrature per segment).
  double arcLength() const;

  // At parameter l (mm), clamped to [0, parameterLength()].
  Vec3 position(double l) const;
  Vec3 derivative(double l) const;
  Vec3 secondDerivative(double l) const;
  double curvature(double l) const;  // mm^-1

  // Points (first and last included) whose chords stay within `tolerance` (mm) of the curve:
  // each segment is halved until the largest distance of the curve from the chord, checked at
  // evenly spaced points between samples, is within the tolerance. Data points are kept.
  std::vector<Vec3> resample(double tolerance = 0.001) const;

 private:
  std::size_t segmentAt(double l) const;
  std::vector<CubicSegment> segments_;
};

// Solves a tridiagonal system (Thomas algorithm) in place: sub[i] x[i-1] + diag[i] x[i] +
// super[i] x[i+1] = rhs[i]; sub[0] and super[n-1] are ignored. Needs a diagonally dominant
// system (as the spline's is); the result replaces rhs.
void solveTridiagonal(std::vector<double> sub, std::vector<double> diag, std::vector<double> super,
                      std::vector<double>& rhs);

// The natural cubic spline through the points (second derivative zero at both ends), in the
// chord-length parameter, for comparison with the Akima spline. Consecutive duplicates are
// dropped; fewer than two distinct points give an empty curve; two give a straight line.
PiecewiseCubicCurve fitNaturalCubicSpline(const std::vector<Vec3>& points);

// The points with consecutive duplicates (closer than kLengthEpsilon) dropped.
std::vector<Vec3> distinctPoints(const std::vector<Vec3>& points);

}  // namespace isurface
