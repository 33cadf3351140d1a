#pragma once
// The exact geometry of one motion move, evaluated by arc length.
#include "isurface/gcode/arc.h"
#include "isurface/gcode/program.h"

#include <limits>

namespace isurface {

// The point of a segment nearest to a given point.
struct PathPoint {
  double distance = std::numeric_limits<double>::infinity();  // mm
  Vec3 tangent = Vec3::Zero();  // unit direction of travel there (zero on a degenerate move)
  double along = 0;             // mm of the move's length before the nearest point
};

struct PathSegment {
  bool arc = false;
  Vec3 start = Vec3::Zero();
  Vec3 end = Vec3::Zero();
  Vec3 direction = Vec3::Zero();  // unit, lines only
  ArcGeometry arcGeometry;        // arcs only
  double length = 0;              // mm

  static PathSegment from(const Program& program, std::size_t moveIndex);
  // The same for a move that starts at `start`.
  static PathSegment from(const Vec3& start, const Move& move);

  // Point at arc length s (mm) from the start; s is clamped to [0, length].
  Vec3 at(double s) const;
  Vec3 startTangent() const { return arc ? arcGeometry.tangentAt(0) : direction; }
  Vec3 endTangent() const { return arc ? arcGeometry.tangentAt(1) : direction; }
  // The nearest point to `p` (on arcs: found within 1 nm of arc length).
  PathPoint nearest(const Vec3& p) const;
};

}  // namespace isurface
