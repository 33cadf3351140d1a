// Samples from G-code lines and points, and the motion at one sample.
#include "isurface/core/locate.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "isurface/core/biip.h"
#include "isurface/core/kinematics.h"

namespace isurface {

namespace {

// Samples on either side that the kinematics stencils can reach (two) plus one, so that the
// window's own ends never decide the value at its middle.
constexpr std::size_t kWindow = 3;

// The nearest of n samples whose coordinates come from get(i, x, y, z).
template <class Get>
std::optional<std::size_t> nearestOf(std::size_t n, const Vec3& point, Get&& get) {
  std::optional<std::size_t> best;
  double bestD = std::numeric_limits<double>::infinity();
  const double px = point.x(), py = point.y(), pz = point.z();
  for (std::size_t i = 0; i < n; ++i) {
    double x, y, z;
    get(i, x, y, z);
    const double dx = x - px, dy = y - py, dz = z - pz;
    const double d = dx * dx + dy * dy + dz * dz;
    // NaN compares false: non-finite samples are never nearest.
    if (d < bestD) {
      bestD = d;
      best = i;
    }
  }
  return best;
}

SampleMotion motionFromWindow(const double* x, const double* y, const double* z, const double* t, std::size_t n,
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

}  // namespace

std::optional<std::size_t> firstSampleOfLine(const Trajectory& samples, std::uint32_t line) {
  const auto it = std::find(samples.line.begin(), samples.line.end(), line);
  if (it == samples.line.end() || (line == 0 && !samples.hasLine)) return std::nullopt;
  return static_cast<std::size_t>(it - samples.line.begin());
}

std::optional<std::size_t> nearestSample(const Trajectory& samples, const Vec3& point) {
  const double *x = samples.x.data(), *y = samples.y.data(), *z = samples.z.data();
  return nearestOf(samples.size(), point, [&](std::size_t i, double& a, double& b, double& c) {
    a = x[i];
    b = y[i];
    c = z[i];
  });
}

std::optional<std::size_t> firstSampleOfLine(const BiipReader& reader, std::uint32_t line) {
  const BiipChannelView view = reader.channel("line");
  if (!view.valid()) return std::nullopt;
  const std::size_t n = reader.recordCount();
  for (std::size_t i = 0; i < n; ++i)
    if (view.integer(i) == line) return i;
  return std::nullopt;
}

std::optional<std::size_t> nearestSample(const BiipReader& reader, const Vec3& point) {
  const BiipChannelView x = reader.channel("x"), y = reader.channel("y"), z = reader.channel("z");
  return nearestOf(reader.recordCount(), point, [&](std::size_t i, double& a, double& b, double& c) {
    a = x[i];
    b = y[i];
    c = z[i];
  });
}

SampleMotion motionAtSample(const Trajectory& samples, std::size_t sample) {
  const std::size_t from = sample >= kWindow ? sample - kWindow : 0;
  const std::size_t to = std::min(samples.size(), sample + kWindow + 1);
  const double* t = samples.irregularTime ? samples.time.data() + from : nullptr;
  return motionFromWindow(samples.x.data() + from, samples.y.data() + from, samples.z.data() + from, t, to - from,
                          sample - from, samples.cycle);
}

SampleMotion motionAtSample(const BiipReader& reader, std::size_t sample) {
  const std::size_t n = reader.recordCount();
  const std::size_t from = sample >= kWindow ? sample - kWindow : 0;
  const std::size_t to = std::min(n, sample + kWindow + 1);
  const std::size_t count = to - from;
  double x[2 * kWindow + 1], y[2 * kWindow + 1], z[2 * kWindow + 1], t[2 * kWindow + 1];
  reader.copyChannel("x", x, from, count);
  reader.copyChannel("y", y, from, count);
  reader.copyChannel("z", z, from, count);
  // Divided differences only when the dump's time channel is irregular, as for a loaded one.
  bool irregular = false;
  const BiipChannelView time = reader.channel("t");
  if (time.valid()) {
    const double cycle = reader.header().cycleSeconds;
    for (std::size_t i = 1; i < n && !irregular; ++i)
      irregular = !(std::fabs(time[i] - time[i - 1] - cycle) <= 1e-3 * cycle);
    if (irregular) reader.copyChannel("t", t, from, count);
  }
  return motionFromWindow(x, y, z, irregular ? t : nullptr, count, sample - from, reader.header().cycleSeconds);
}

}  // namespace isurface
