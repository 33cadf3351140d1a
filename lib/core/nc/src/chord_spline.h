#pragma once
// The curve a jerk-limited generic control runs through a run of CAM chords: between two chord
// points, a quintic that passes through both with the tangent and the curvature of the circle
// through each point and its neighbours. Consecutive pieces share tangent and curvature at
// their common point, so the path's curvature is continuous along the run, as the surface's
// is, instead of a kink at every chord junction that the axes' filters must smooth by braking
// (Siemens COMPCAD, Fanuc nano smoothing and Heidenhain ADP fit the chord points the same way).
// Units: mm, 1/mm.
#include <array>

#include "isurface/base/geometry.h"

namespace isurface {

// The path's direction and curvature at a chord point.
struct ChordKnot {
  Vec3 tangent = Vec3::Zero();    // unit, in the direction of travel
  Vec3 curvature = Vec3::Zero();  // towards the centre of curvature, of length 1 / radius (1/mm)

  // The tangent and curvature of the circle through `previous`, `point` and `next`, at `point`;
  // along `next - previous` with no curvature where the three are collinear.
  static ChordKnot through(const Vec3& previous, const Vec3& point, const Vec3& next);
  // A straight end: the chord's own direction.
  static ChordKnot straight(const Vec3& from, const Vec3& to);
};

class ChordSpline {
 public:
  // The piece from `start` to `end` (distinct points) with these ends.
  ChordSpline(const Vec3& start, const ChordKnot& startKnot, const Vec3& end, const ChordKnot& endKnot);

  double length() const { return cumulative_.back(); }  // mm
  Vec3 at(double s) const;          // s: mm from the start, clamped to the length
  Vec3 tangentAt(double s) const;   // unit
  Vec3 start() const { return c_[0]; }
  Vec3 end() const { return point(1.0); }
  Vec3 startTangent() const { return tangentAt(0.0); }
  Vec3 endTangent() const { return tangentAt(length()); }

  // What the planner judges the curve by, at 33 points along it.
  struct Shape {
    double largestCurvature = 0;          // 1/mm
    Vec3 largestDirection = Vec3::Zero();  // per axis, the largest |component| of the unit tangent
    // Whether it runs from start to end without turning back on itself: everywhere at least
    // half its speed along the chord.
    bool wellFormed = true;
  };
  Shape shape() const;
  // The farthest it strays from the segment a-b, mm (at 33 points along it).
  double farthestFrom(const Vec3& a, const Vec3& b) const;

 private:
  // The arc-length table: spans of equal parameter, each measured by Gauss-Legendre; between
  // its nodes the parameter is a cubic in arc length with the slopes 1 / |p'| of the nodes.
  static constexpr int kSpans = 8;
  Vec3 point(double u) const;
  Vec3 derivative(double u) const;
  Vec3 secondDerivative(double u) const;
  double parameterAt(double s) const;

  std::array<Vec3, 6> c_;  // monomial coefficients in u in [0, 1]
  std::array<double, kSpans + 1> cumulative_{};
  std::array<double, kSpans + 1> slope_{};  // du/ds at the nodes
};

}  // namespace isurface
