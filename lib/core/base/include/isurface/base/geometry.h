#pragma once
// Basic geometric vocabulary shared by every core module. All lengths are millimetres.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "isurface/base/tolerances.h"
#include "isurface/base/units.h"

namespace isurface {

using Vec3 = Eigen::Vector3d;

// Active arc plane, named by the G-code that selects it. The plane's first and second axes
// (u, v) and its normal axis (w) are chosen so that counter-clockwise (G3) is a positive
// rotation about +w: G17 (u=X, v=Y, w=Z), G18 (u=Z, v=X, w=Y), G19 (u=Y, v=Z, w=X).
enum class Plane : unsigned char { XY = 17, ZX = 18, YZ = 19 };

struct PlaneAxes {
  int u, v, w;
};

inline PlaneAxes planeAxes(Plane plane) {
  switch (plane) {
    case Plane::ZX: return {2, 0, 1};
    case Plane::YZ: return {1, 2, 0};
    case Plane::XY:
    default: return {0, 1, 2};
  }
}

// Radius of the circle through three points (equation 1 of the constant speed interval
// paper), mm; +infinity for collinear or coincident points.
double threePointRadius(const Vec3& previous, const Vec3& point, const Vec3& next);

// Distance from p to the segment a-b, mm; a segment shorter than kLengthEpsilon is its start.
double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b);

// Whether the way from `from` to `to` runs against the axes: its largest component is
// negative. A path and the same path run back give opposite answers (whatever the digits of its
// smaller components), so that work done one canonical way is the same for both.
bool runsBackwards(const Vec3& from, const Vec3& to);

// Whether (x, y) lies in the box seen from above, its sides included (kOnBoxSide).
inline bool insideBoxInPlan(double x, double y, const Vec3& lower, const Vec3& upper) {
  return x >= lower.x() - kOnBoxSide && x <= upper.x() + kOnBoxSide && y >= lower.y() - kOnBoxSide &&
         y <= upper.y() + kOnBoxSide;
}

}  // namespace isurface
