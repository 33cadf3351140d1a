#pragma once
// A pass's corners cut by arcs inside a tube around it. A corner the path turns by theta at is
// replaced by an arc tangent to both legs whose chords pass no further than `tube` (mm) from the
// corner, written as chords that each turn the path by at most `pieceTurn` (rad), or fewer where
// they would be shorter than 0.02 mm (a small arc at a sharp corner). The machine
// then turns the corner along a curve instead of a velocity step, which a jerk-limited
// interpolator passes by braking to a speed at which the step fits its jerk budget.
// Unlike a spline through the points (which keeps every point, so its bulges between points grow
// with their corners), the arc leaves the corner point itself: the new polyline lies within
// `tube` of the old one, and the old one within `tube` of the new.
#include <cstddef>
#include <vector>

#include "isurface/base/geometry.h"

namespace isurface {

struct RoundedPath {
  std::vector<Vec3> points;
  // Per new segment k (from points[k] to points[k + 1]), the old segment it stands for.
  std::vector<std::size_t> oldSegment;
};

RoundedPath roundedCorners(const std::vector<Vec3>& points, double tube, double pieceTurn);

}  // namespace isurface
