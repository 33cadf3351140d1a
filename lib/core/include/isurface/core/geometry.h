#pragma once
// Basic geometric vocabulary shared by every core module. All lengths are millimetres.
#include <Eigen/Core>
#include <Eigen/Geometry>

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

// Lengths below this are treated as zero (mm). Well below any machine's resolution.
constexpr double kLengthEpsilon = 1e-9;

}  // namespace isurface
