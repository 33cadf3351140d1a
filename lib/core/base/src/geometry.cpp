// Geometry shared by planning and fitting.
#include "isurface/base/geometry.h"

#include <limits>

namespace isurface {

double threePointRadius(const Vec3& previous, const Vec3& point, const Vec3& next) {
  const Vec3 a = next - point, b = point - previous, c = next - previous;
  const double cross = a.cross(b).norm();
  const double lengths = a.norm() * b.norm() * c.norm();
  if (!(cross > kCollinearRelative * lengths) || lengths == 0) return std::numeric_limits<double>::infinity();
  return lengths / (2.0 * cross);
}

}  // namespace isurface
