#pragma once
// Akima spline through CL points in the chord-length parameter (section 3 of "Constant speed
// interval and quality prediction", equations 2-6). With points P_0..P_{N-1} (0-based here):
//   h_i = |P_{i+1} - P_i|, m_i = (P_{i+1} - P_i) / h_i                           (eq. 2)
//   m_{-1} = 2 m_0 - m_1, m_{-2} = 2 m_{-1} - m_0,
//   m_{N-1} = 2 m_{N-2} - m_{N-3}, m_N = 2 m_{N-1} - m_{N-2}                      (eq. 4)
//   s_i = (|m_{i+1} - m_i| m_{i-1} + |m_{i-1} - m_{i-2}| m_i)
//         / (|m_{i+1} - m_i| + |m_{i-1} - m_{i-2}|),  or (m_{i-1} + m_i) / 2 when the
//         denominator is 0                                                         (eq. 5)
//   A = P_i, B = s_i, C = (3 m_i - 2 s_i - s_{i+1}) / h_i,
//   D = (-2 m_i + s_i + s_{i+1}) / h_i^2                                          (eq. 6)
// Choices where the paper is open:
//  - The weights of eq. 5 are taken per axis, from the absolute differences of that axis' slopes
//    (classic one-dimensional Akima applied to x(l), y(l), z(l)).
//  - D uses +s_{i+1}: the printed "- s(l_{i+1})" is a typo, since only the + sign makes the
//    segment end at P_{i+1} with tangent s_{i+1} (cubic Hermite).
//  - Two points give a straight line (s = m_0); eq. 4 needs at least three.
//  - Consecutive duplicate points are dropped (their chord would be zero).
#include <optional>
#include <vector>

#include "isurface/fitting/cubic_spline.h"

namespace isurface {

// Fits point by point, as the paper's recursive fitting does: each segment is emitted once the
// tangent at its end is known (two points later, by eq. 5), and that end tangent is kept as the
// next segment's start tangent, so consecutive segments are G1 continuous by construction.
class IncrementalAkimaFitter {
 public:
  // Adds the next point; returns the segment that became complete, if any.
  std::optional<CubicSegment> add(const Vec3& point);
  // No more points: returns the segments still waiting for their end tangents.
  std::vector<CubicSegment> finish();
  // Every segment emitted so far, in order.
  const std::vector<CubicSegment>& segments() const { return emitted_; }

 private:
  Vec3 tangentAt(std::size_t i) const;  // s_i for an interior point with m_{i-2}..m_{i+1} known
  Vec3 slope(long i) const;             // m_i including the auxiliary start slopes
  CubicSegment makeSegment(std::size_t i, const Vec3& startTangent, const Vec3& endTangent) const;

  std::vector<Vec3> points_;
  std::vector<Vec3> slopes_;       // m_0 .. m_{N-2}
  std::vector<double> starts_;     // l_i
  std::vector<CubicSegment> emitted_;
  Vec3 pendingTangent_ = Vec3::Zero();  // start tangent of the next segment to emit
  bool finished_ = false;
};

// The whole spline at once: all slopes, then all tangents, then all coefficients. Gives the same
// segments as the incremental fitter.
PiecewiseCubicCurve fitAkimaSpline(const std::vector<Vec3>& points);

// Eq. 5 for one axis (also used by the fitter); m2..p1 are m_{i-2}, m_{i-1}, m_i, m_{i+1}.
double akimaTangent(double m2, double m1, double m0, double p1);

}  // namespace isurface
