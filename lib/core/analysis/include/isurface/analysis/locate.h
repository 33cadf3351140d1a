#pragma once
// Linking samples, G-code lines and points in space (the paper's locate functions).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

#include "isurface/base/trajectory.h"

namespace isurface {

// The first sample produced by a G-code line (as the paper's locate does), if any.
std::optional<std::size_t> firstSampleOfLine(const Trajectory& samples, std::uint32_t line);

// The sample nearest to a point (commanded positions), if there are samples.
std::optional<std::size_t> nearestSample(const Trajectory& samples, const Vec3& point);

// Motion parameters at one sample, from the samples around it with kinematics.h's formulas
// (the values deriveKinematics gives for the whole trajectory).
struct SampleMotion {
  double speed = 0;           // mm/s, path
  double accel = 0;           // mm/s^2, tangential (signed)
  double accelMagnitude = 0;  // mm/s^2
  double jerk = 0;            // mm/s^3, |j|
  Vec3 velocity = Vec3::Zero();      // mm/s, per axis
  Vec3 acceleration = Vec3::Zero();  // mm/s^2, per axis
  Vec3 jerkAxes = Vec3::Zero();      // mm/s^3, per axis
};

// `sample` must be below the number of samples.
SampleMotion motionAtSample(const Trajectory& samples, std::size_t sample);

// Samples on either side that the kinematics stencils can reach (two) plus one, so that the
// window's own ends never decide the value at its middle.
constexpr std::size_t kMotionWindow = 3;

// The motion at sample `local` of a window of n samples (t nullptr: a regular cycle, s).
SampleMotion motionInWindow(const double* x, const double* y, const double* z, const double* t, std::size_t n,
                            std::size_t local, double cycle);

// The nearest of n samples whose coordinates come from get(i, x, y, z), mm; non-finite samples
// are never nearest.
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
    if (d < bestD) {  // NaN compares false
      bestD = d;
      best = i;
    }
  }
  return best;
}

}  // namespace isurface
