#include "isurface/fitting/akima_spline.h"

#include <cmath>

namespace isurface {

namespace {

CubicSegment hermiteSegment(double start, const Vec3& p, const Vec3& q, const Vec3& s0, const Vec3& s1) {
  CubicSegment seg;
  seg.start = start;
  seg.length = (q - p).norm();
  const double h = seg.length;
  const Vec3 m = (q - p) / h;
  seg.a = p;
  seg.b = s0;
  seg.c = (3.0 * m - 2.0 * s0 - s1) / h;
  seg.d = (-2.0 * m + s0 + s1) / (h * h);
  return seg;
}

Vec3 tangentFromSlopes(const Vec3& m2, const Vec3& m1, const Vec3& m0, const Vec3& p1) {
  Vec3 s;
  for (int a = 0; a < 3; ++a) s[a] = akimaTangent(m2[a], m1[a], m0[a], p1[a]);
  return s;
}

}  // namespace

double akimaTangent(double m2, double m1, double m0, double p1) {
  const double w1 = std::abs(p1 - m0);  // weight of m_{i-1}
  const double w0 = std::abs(m1 - m2);  // weight of m_i
  // Exactly zero, as in eq. 5: any positive weight sum gives a well-defined average.
  if (w1 + w0 == 0.0) return 0.5 * (m1 + m0);
  return (w1 * m1 + w0 * m0) / (w1 + w0);
}

// --- Incremental ---

Vec3 IncrementalAkimaFitter::slope(long i) const {
  // Auxiliary start slopes (eq. 4); needs m_0 and m_1.
  if (i == -1) return 2.0 * slopes_[0] - slopes_[1];
  if (i == -2) return 2.0 * slope(-1) - slopes_[0];
  return slopes_[static_cast<std::size_t>(i)];
}

Vec3 IncrementalAkimaFitter::tangentAt(std::size_t i) const {
  const long k = static_cast<long>(i);
  return tangentFromSlopes(slope(k - 2), slope(k - 1), slope(k), slope(k + 1));
}

CubicSegment IncrementalAkimaFitter::makeSegment(std::size_t i, const Vec3& s0, const Vec3& s1) const {
  return hermiteSegment(starts_[i], points_[i], points_[i + 1], s0, s1);
}

std::optional<CubicSegment> IncrementalAkimaFitter::add(const Vec3& point) {
  if (finished_) return std::nullopt;
  if (!points_.empty() && (point - points_.back()).norm() < kLengthEpsilon) return std::nullopt;
  if (!points_.empty()) {
    const Vec3 chord = point - points_.back();
    starts_.push_back(starts_.empty() ? 0.0 : starts_.back() + (points_.back() - points_[points_.size() - 2]).norm());
    slopes_.push_back(chord / chord.norm());
  }
  points_.push_back(point);
  // With m_0, m_1 known (three points) the start tangent s_0 follows from the auxiliary slopes.
  if (slopes_.size() == 2) pendingTangent_ = tangentAt(0);
  // s_i needs m_{i+1}: with slopes m_0..m_{k}, s_{k-1} is known, which ends segment k-2.
  if (slopes_.size() >= 3) {
    const std::size_t i = slopes_.size() - 3;  // segment to emit
    const Vec3 end = tangentAt(i + 1);
    emitted_.push_back(makeSegment(i, pendingTangent_, end));
    pendingTangent_ = end;
    return emitted_.back();
  }
  return std::nullopt;
}

std::vector<CubicSegment> IncrementalAkimaFitter::finish() {
  std::vector<CubicSegment> out;
  if (finished_) return out;
  finished_ = true;
  const std::size_t n = points_.size();
  if (n < 2) return out;
  if (n == 2) {
    out.push_back(makeSegment(0, slopes_[0], slopes_[0]));
  } else {
    // Auxiliary end slopes (eq. 4): m_{N-1} and m_N extend the slope sequence past the end.
    const Vec3 mEnd1 = 2.0 * slopes_[n - 2] - slopes_[n - 3];
    const Vec3 mEnd2 = 2.0 * mEnd1 - slopes_[n - 2];
    const Vec3 mBefore = n >= 4 ? slopes_[n - 4] : slope(-1);
    const Vec3 sSecondLast = tangentFromSlopes(mBefore, slopes_[n - 3], slopes_[n - 2], mEnd1);
    const Vec3 sLast = tangentFromSlopes(slopes_[n - 3], slopes_[n - 2], mEnd1, mEnd2);
    out.push_back(makeSegment(n - 3, pendingTangent_, sSecondLast));
    out.push_back(makeSegment(n - 2, sSecondLast, sLast));
  }
  emitted_.insert(emitted_.end(), out.begin(), out.end());
  return out;
}

// --- Batch ---

PiecewiseCubicCurve fitAkimaSpline(const std::vector<Vec3>& input) {
  const std::vector<Vec3> p = distinctPoints(input);
  const std::size_t n = p.size();
  if (n < 2) return {};
  if (n == 2) return PiecewiseCubicCurve({hermiteSegment(0, p[0], p[1], (p[1] - p[0]).normalized(), (p[1] - p[0]).normalized())});
  // Slopes with two auxiliary ones at each end: m[k + 2] holds m_k for k = -2 .. N.
  std::vector<Vec3> m(n + 3);
  for (std::size_t i = 0; i + 1 < n; ++i) m[i + 2] = (p[i + 1] - p[i]).normalized();
  m[1] = 2.0 * m[2] - m[3];
  m[0] = 2.0 * m[1] - m[2];
  m[n + 1] = 2.0 * m[n] - m[n - 1];
  m[n + 2] = 2.0 * m[n + 1] - m[n];
  std::vector<Vec3> s(n);
  for (std::size_t i = 0; i < n; ++i) s[i] = tangentFromSlopes(m[i], m[i + 1], m[i + 2], m[i + 3]);
  std::vector<CubicSegment> segments;
  double l = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    segments.push_back(hermiteSegment(l, p[i], p[i + 1], s[i], s[i + 1]));
    l += segments.back().length;
  }
  return PiecewiseCubicCurve(std::move(segments));
}

}  // namespace isurface
