#pragma once
// Exact arc geometry: circular or helical, in one of the three planes, possibly spiral when the
// end radius differs slightly from the start radius (the radius then varies linearly with angle).
#include "isurface/gcode/program.h"

namespace isurface {

struct ArcGeometry {
  PlaneAxes axes{0, 1, 2};
  Vec3 centre = Vec3::Zero();  // the plane-normal coordinate is the start's
  double startAngle = 0;       // rad, in the (u, v) plane
  double sweep = 0;            // rad, signed: > 0 counter-clockwise about +w
  double startRadius = 0;      // mm
  double endRadius = 0;        // mm
  double startW = 0, endW = 0; // mm, along the plane normal (helix)

  // Build from a move and its start point. Never fails: a degenerate arc has zero length.
  static ArcGeometry from(const Vec3& start, const Move& move);

  double length() const;                  // mm, helical length
  Vec3 at(double fraction) const;         // point at fraction of the sweep, 0..1
  Vec3 tangentAt(double fraction) const;  // unit tangent in the direction of travel
  double minRadius() const { return startRadius < endRadius ? startRadius : endRadius; }
};

}  // namespace isurface
