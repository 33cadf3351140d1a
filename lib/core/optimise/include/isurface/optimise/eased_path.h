#pragma once
// A pass's bends eased in and out: the curvature of a smooth path made continuous where a bend
// meets a straight, inside a tube around the program's path.
//
// A fillet written as an arc tangent to a plane and a slope steps from no curvature to 1/R at
// its ends. The servo, its normal acceleration stepping with it, overshoots the deviation it
// settles at inside the bend, and the speed, held to sqrt(a * R) across the whole bend, may only
// rise once the straight begins. Averaged along its length over a window of L (twice: a
// triangle), the path's curvature instead rises and falls over the window, as along a pair of
// clothoids, and the arc moves toward its centre by about L^2 / (12 R): the speed held to a
// normal acceleration can follow the curvature down as the bend eases out.
#include <cmath>
#include <cstddef>
#include <vector>

#include "isurface/base/geometry.h"

namespace isurface {

struct EasedPath {
  std::vector<Vec3> points;
  // Per new segment k (from points[k] to points[k + 1]), the segment of `program` it lies beside.
  std::vector<std::size_t> oldSegment;
  // mm, the width of the averaging window chosen (twice applied, it reaches twice as far; 0:
  // the path is `smooth` unchanged).
  double window = 0;
};

struct EasingLimits {
  double tube = 0.008;             // mm, how far the eased path may be from the program's, both ways
  double chordTolerance = 0.005;   // mm, how far a chord written may stray from the eased path
  double maxTurn = 0.01;           // rad, about the most the path turns between two chords
  // 1/mm: sharper than this, a bend is written in pieces of at most 0.05 mm (where its feed is
  // held below the program's, so that ramps change it in fine steps); INFINITY: nowhere.
  double bendCurvature = INFINITY;
};

// `smooth`: the pass's path fitted through `program`'s points (dense, small turns), mm. The
// widest window (at most 4 mm) is chosen whose path lies within the tube of `program`'s
// polyline both ways.
EasedPath easedPath(const std::vector<Vec3>& smooth, const std::vector<Vec3>& program, const EasingLimits& limits);

}  // namespace isurface
