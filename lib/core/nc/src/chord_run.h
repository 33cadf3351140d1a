#pragma once
// A run of CAM chords on its way to the planner: where the generic control's curve through the
// run passes each chord point, and in which direction and with which curvature
// (chord_spline.h). Chord points are rounded to the program's digits (0.1 um in four decimals):
// on chords of 0.05 mm that alone turns the circle through three points by a milliradian, a
// curvature of 1/25 mm of noise. So each point's direction and curvature come from a quadratic
// fitted by least squares to the points within kFitReach of it along the run, and the curve
// passes the fitted point (no farther than the fit's residual from the programmed one), as the
// compressors of controls smooth points within their tolerance. The run's first and last points
// are its corners with the moves around it and are kept exactly. Units: mm.
#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "isurface/gcode/path_segment.h"

#include "chord_spline.h"

namespace isurface {

// Where a chord's curve starts or ends: its offset from the programmed point and its knot.
struct CurveEnd {
  Vec3 offset = Vec3::Zero();
  ChordKnot knot;
};

// The curve ends a planned segment keeps for the interpolator (PlannedSegment::chordCurve), in
// single precision: 1e-7 of a tangent, or of a 0.01 mm offset, is far below a nanometre over a
// chord. The planner builds its curve from the same rounded values, so that both run one curve.
std::array<float, 18> packCurve(const CurveEnd& start, const CurveEnd& end);
CurveEnd unpackCurveEnd(const std::array<float, 18>& packed, bool atEnd);
// The curve of move `seg` with these packed ends.
ChordSpline curveOf(const PathSegment& seg, const std::array<float, 18>& packed);

// A chord leaving the run, with its curve's ends (none: a run of one chord, run as the line).
struct FittedChord {
  std::uint32_t index = 0;  // of its move in the program
  Move move;
  PathSegment seg;
  std::optional<CurveEnd> start, end;
};

class ChordRun {
 public:
  // Half the stretch of run (mm) a point's quadratic is fitted to, and the most points on each side.
  static constexpr double kFitReach = 0.5;
  static constexpr std::size_t kMostFitPoints = 24;

  // `largestOffset`: the farthest (mm) the curve may pass a chord point; a fit farther off
  // passes the point itself.
  explicit ChordRun(double largestOffset) : largestOffset_(largestOffset) {}

  bool empty() const { return chords_.empty(); }
  // The next chord of the run (it starts where the last ended and the caller found that the two
  // join smoothly), or the first of a new run when the run is empty.
  void push(std::uint32_t index, const Move& move, const PathSegment& seg);
  // No chord joins the run after the last pushed: its last point is a corner.
  void end();
  // The chords whose curve is settled, in order.
  void take(std::vector<FittedChord>& out);

 private:
  struct Point {
    Vec3 position;
    double along = 0;  // mm of chord length from the run's first point
  };
  // Where the curve passes run point `i`: exactly, along its chord, at the run's ends.
  CurveEnd fitAt(std::size_t i) const;
  bool settled(std::size_t i) const;
  const Point& pointAt(std::size_t i) const { return points_[i - dropped_]; }

  // Run point i is points_[i - dropped_]; chords_.front() runs from run point firstChord_ to the next.
  std::deque<FittedChord> chords_;
  std::deque<Point> points_;
  std::size_t dropped_ = 0, firstChord_ = 0;
  CurveEnd nextStart_;  // where the front chord's curve starts (its predecessor's end)
  bool ended_ = false;
  double largestOffset_;
};

}  // namespace isurface
