// Geometry shared by planning and fitting.
#include "isurface/base/geometry.h"

#include <algorithm>
#include <limits>

namespace isurface {

double threePointRadius(const Vec3& previous, const Vec3& point, const Vec3& next) {
  const Vec3 a = next - point, b = point - previous, c = next - previous;
  const double cross = a.cross(b).norm();
  const double lengths = a.norm() * b.norm() * c.norm();
  if (!(cross > kCollinearRelative * lengths) || lengths == 0) return std::numeric_limits<double>::infinity();
  return lengths / (2.0 * cross);
}

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 < kLengthEpsilon * kLengthEpsilon) return (p - a).norm();
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

bool runsBackwards(const Vec3& from, const Vec3& to) {
  const Vec3 d = to - from;
  Eigen::Index axis = 0;
  d.cwiseAbs().maxCoeff(&axis);
  return d[axis] < 0;
}

}  // namespace isurface
