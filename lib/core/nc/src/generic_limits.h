#pragma once
// The generic control's speed limits: a segment's (its feed, axes and curvature), a corner's
// between two segments, and those of the blend that may replace a corner, given the filters
// after interpolation that the control smooths its positions with (the paper's NC model), so that
// the path stays within the machine's tolerance. Units: mm, s.
#include "isurface/gcode/path_segment.h"
#include "isurface/machine/machine.h"
#include "isurface/nc/feed_plan.h"

#include "chord_spline.h"
#include "corner_blend.h"

namespace isurface {

// A corner blend considered at a junction: how far it reaches (0: none), the smoothing tolerance
// it leaves the filters' rounding of it (mm) and its speed limit (mm/s).
struct BlendChoice {
  double reach = 0, filterTolerance = 0, speed = 0;
};

class GenericLimits {
 public:
  GenericLimits(const Machine& machine, const LimitBudget& budget);

  double filterTime1() const { return t1_; }  // s, the jerk filter's
  double filterTime2() const { return t2_; }  // s, the corner filter's
  double settleTime() const { return t1_ + t2_; }  // s for the filters to drain

  // mm/s: the speed a segment may have (its feed, the axes' speeds along it, on an arc its
  // curvature); not above 0 where the feed or the rapid rate is not.
  double segmentSpeed(const PathSegment& seg, const Move& move) const;
  // The acceleration along the path that keeps every axis within its share, mm/s^2.
  double tangentialAccel(const PathSegment& seg) const;
  // The tangential acceleration (mm/s^2) on a curve of radius r (mm) whose share of the filters'
  // deviation, a^2 E[S^4] / 4, is at most half of 2 r `tolerance` (mm).
  double curveAccelLimit(double radius, double tolerance) const;
  double smoothingTolerance() const { return smoothingTolerance_; }  // mm

  // The speed (mm/s) at which the corner where `in` ends and `out` starts may be passed; 0 where
  // it is too sharp to pass in motion: then stop there for `hold` seconds. `accelIn`: the ramps'
  // acceleration on `in`. `junction`: the path's directions there (a chord curve's, where one
  // side is run as one); between two straight lines, `radius` is the circle's through three
  // points (mm).
  struct Junction {
    Vec3 inTangent, outTangent;
    bool betweenLines;
  };
  double cornerLimit(const PathSegment& in, const PathSegment& out, const Junction& junction, double accelIn,
                     double& hold, double& radius) const;
  // A run of chords as a curve (chord_spline.h): its speed limit (mm/s; its feed, the axes'
  // speeds along its steepest directions, its tightest curvature) and its ramps' acceleration
  // (mm/s^2).
  double chordCurveSpeed(const ChordSpline::Shape& curve, const Move& move) const;
  double chordCurveAccel(const ChordSpline::Shape& curve) const;
  BlendChoice blendAt(const PathSegment& in, const PathSegment& out, const Move& move) const;
  // The ramps' acceleration on a blend, mm/s^2.
  double blendAccel(const CornerBlend& blend) const;

 private:
  // Speed limit on a curve of radius r (mm): centripetal acceleration and its turning rate,
  // the deviation the filters cause on a curve, and (arcs) the chord error between samples.
  // `accel`: the axes' acceleration in the curve's plane; `rampBound`: the most its ramps may use
  // (filterAccel_). `onArc`: an exact arc, whose ramps are held within curveAccelLimit; else the
  // radius through three points of short G1 moves. `tolerance`: the filters' share, mm.
  double curvatureLimit(double radius, double accel, double rampBound, bool onArc, double tolerance) const;
  double blendSpeed(const CornerBlend& blend, const Move& move, double filterTolerance) const;
  // E[S^2] and E[S^4] of the filters' combined delay S = U1 + U2 (U uniform over T1 and T2).
  double filterMoment2() const { return (t1_ * t1_ + t2_ * t2_) / 12.0; }
  double filterMoment4() const;

  const Machine& machine_;
  const LimitBudget budget_;
  double t1_ = 0, t2_ = 0;
  // mm/s^2 per axis: the most a ramp may use with the jerk filter T1 (the tangential share of
  // jerk over T1 / 2; without a jerk limit, the tangential share of acceleration), which bounds
  // the filters' deviation whatever the acceleration limits are; and what ramps use (also within
  // the tangential share of acceleration).
  Vec3 filterAccel_ = Vec3::Zero(), rampAccel_ = Vec3::Zero();
  double smoothingTolerance_ = 0;  // mm, the share of the chord tolerance for rounding
};

}  // namespace isurface
