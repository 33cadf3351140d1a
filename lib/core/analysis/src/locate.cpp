// Samples from G-code lines and points, and the motion at one sample.
#include "isurface/analysis/locate.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "isurface/analysis/kinematics.h"

namespace isurface {

SampleMotion motionInWindow(const double* x, const double* y, const double* z, const double* t, std::size_t n,
                              std::size_t local, double cycle) {
  const Kinematics k = deriveKinematics(x, y, z, t, n, cycle, true);
  SampleMotion m;
  m.speed = k.speed[local];
  m.accel = k.accel[local];
  m.accelMagnitude = k.accelMagnitude[local];
  m.jerk = k.jerk[local];
  for (int a = 0; a < 3; ++a) {
    m.velocity[a] = k.axisVel[a][local];
    m.acceleration[a] = k.axisAcc[a][local];
    m.jerkAxes[a] = k.axisJerk[a][local];
  }
  return m;
}

std::optional<std::size_t> firstSampleOfLine(const Trajectory& samples, std::uint32_t line) {
  if (line == 0 && !samples.hasLine) return std::nullopt;
  const RunChannel<std::uint32_t>& lines = samples.line;
  for (std::size_t r = 0; r < lines.runCount(); ++r)
    if (lines.runValue(r) == line) return lines.runBegin(r);
  return std::nullopt;
}

std::optional<std::size_t> nearestSample(const Trajectory& samples, const Vec3& point) {
  const double *x = samples.x.data(), *y = samples.y.data(), *z = samples.z.data();
  return nearestOf(samples.size(), point, [&](std::size_t i, double& a, double& b, double& c) {
    a = x[i];
    b = y[i];
    c = z[i];
  });
}

SampleMotion motionAtSample(const Trajectory& samples, std::size_t sample) {
  const std::size_t from = sample >= kMotionWindow ? sample - kMotionWindow : 0;
  const std::size_t to = std::min(samples.size(), sample + kMotionWindow + 1);
  const double* t = samples.irregularTime ? samples.time.data() + from : nullptr;
  return motionInWindow(samples.x.data() + from, samples.y.data() + from, samples.z.data() + from, t, to - from,
                          sample - from, samples.cycle);
}

}  // namespace isurface
