#include "linuxcnc_rotary.h"

#include <algorithm>
#include <cmath>

namespace isurface::linuxcnc {

namespace {

// emccanon's `tiny`: a displacement below it is no motion of that axis.
constexpr double kTiny = 1e-7;

}  // namespace

RotaryLimits rotaryLimits(const Machine& m) {
  RotaryLimits r;
  if (!m.kinematics) return r;
  for (int k = 0; k < 2; ++k) {
    const RotaryAxis& axis = m.kinematics->rotary[static_cast<std::size_t>(k)];
    const int i = axis.name - 'A';
    if (i < 0 || i > 2) continue;
    const auto u = static_cast<std::size_t>(i);
    r.present[u] = true;
    r.velocity[u] = axis.maxVelocity;
    r.acceleration[u] = axis.maxAcceleration;
    r.kinematicsIndex[u] = k;
  }
  return r;
}

StraightLimits straightLimits(const Machine& m, const RotaryLimits& r, const Vec3& move, const Vec3& turn) {
  StraightLimits out;
  double slowestByVelocity = 0, slowestByAcceleration = 0;  // s, s^2 of the slowest axis
  Vec3 d = move.cwiseAbs(), t = turn.cwiseAbs();
  for (int i = 0; i < 3; ++i) {
    if (d[i] < kTiny) d[i] = 0;
    if (t[i] < kTiny || !r.present[static_cast<std::size_t>(i)]) t[i] = 0;
  }
  out.linear = d.maxCoeff() > 0;
  out.angular = t.maxCoeff() > 0;
  for (int i = 0; i < 3; ++i) {
    if (out.linear && d[i] > 0) {
      slowestByVelocity = std::max(slowestByVelocity, d[i] / m.axes[i].maxVelocity);
      slowestByAcceleration = std::max(slowestByAcceleration, d[i] / m.axes[i].maxAcceleration);
    }
    const auto u = static_cast<std::size_t>(i);
    if (t[i] > 0) {
      // A limit of 0 is none.
      if (r.velocity[u] > 0) slowestByVelocity = std::max(slowestByVelocity, t[i] / r.velocity[u]);
      if (r.acceleration[u] > 0) slowestByAcceleration = std::max(slowestByAcceleration, t[i] / r.acceleration[u]);
    }
  }
  out.length = out.linear ? d.norm() : t.norm();
  if (slowestByVelocity > 0) out.velocity = out.length / slowestByVelocity;
  if (slowestByAcceleration > 0) out.acceleration = out.length / slowestByAcceleration;
  return out;
}

void capByRotary(const RotaryLimits& r, const Vec3& turn, double length, double& velocity, double& acceleration) {
  for (int i = 0; i < 3; ++i) {
    const auto u = static_cast<std::size_t>(i);
    const double t = std::abs(turn[i]);
    if (t < kTiny || !r.present[u]) continue;
    if (r.velocity[u] > 0) velocity = std::min(velocity, length * r.velocity[u] / t);
    if (r.acceleration[u] > 0) acceleration = std::min(acceleration, length * r.acceleration[u] / t);
  }
}

}  // namespace isurface::linuxcnc
