#include "linuxcnc_segment.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isurface::linuxcnc {

Vec3 Segment::pointAt(double s) const {
  switch (shape) {
    case Shape::Line:
      return target > 0 ? Vec3(start + (end - start) * (s / target)) : start;
    case Shape::Arc:
      return arc.at(target > 0 ? std::clamp(s / target, 0.0, 1.0) : 0.0);
    case Shape::Blend:
      if (s <= lead) return start + direction * s;
      {
        // Interpolated between the radii at both ends (arcPoint's slerp), so that a blend
        // whose ends are at slightly different distances from its centre still meets both.
        const double a = radius > 0 ? std::clamp((s - lead) / radius, 0.0, angle) : 0.0;
        const double sine = std::sin(angle);
        if (sine < 1e-12) return centre + rStart;
        return centre + rStart * (std::sin(angle - a) / sine) + rEnd * (std::sin(a) / sine);
      }
  }
  return start;
}

Vec3 Segment::rotaryAt(double s) const {
  if (!rotates() || target <= 0) return rotaryStart;
  return rotaryStart + (rotaryEnd - rotaryStart) * std::clamp(s / target, 0.0, 1.0);
}

Vec3 Segment::startTangent() const {
  switch (shape) {
    case Shape::Line: return direction;
    case Shape::Arc: return arc.tangentAt(0);
    case Shape::Blend: return direction;
  }
  return direction;
}

Vec3 Segment::endTangent() const {
  switch (shape) {
    case Shape::Line: return direction;
    case Shape::Arc: return arc.tangentAt(1);
    case Shape::Blend: {
      // d/da of the slerp at its end.
      const Vec3 d = rEnd * std::cos(angle) - rStart;
      return d.norm() > 0 ? Vec3(d.normalized()) : direction;
    }
  }
  return direction;
}

double overallAcceleration(const Segment& s) {
  double scale = 1.0 - std::max(s.kinkReduction, s.kinkReductionBefore);
  if (s.blendBefore || s.term == Term::Parabolic) scale *= 0.5;
  return s.maxAcceleration * scale;
}

double tangentialAcceleration(const Segment& s) {
  const double a = overallAcceleration(s);
  return s.curved() ? a * kTangentialShare : a;
}

namespace {

template <typename Limit>
double projectedLimit(const Machine& m, const Vec3& d, Limit limit) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    if (std::abs(d[i]) > 1e-12) best = std::min(best, limit(m.axes[i]) / std::abs(d[i]));
  return best;
}

}  // namespace

double lineVelocityLimit(const Machine& m, const Vec3& d) {
  return projectedLimit(m, d, [](const AxisLimits& a) { return a.maxVelocity; });
}

double lineAccelerationLimit(const Machine& m, const Vec3& d) {
  return projectedLimit(m, d, [](const AxisLimits& a) { return a.maxAcceleration; });
}

double inscribedInPlane(const Vec3& n, const Vec3& bounds) {
  double extent[3];
  for (int i = 0; i < 3; ++i) {
    Vec3 planar = -n * n[i];
    planar[i] += 1.0;
    const double scale = std::max(planar.cwiseAbs().norm(), 1e-12);
    extent[i] = bounds[i] / scale;
  }
  return std::min({extent[0], extent[1], extent[2]});
}

}  // namespace isurface::linuxcnc
