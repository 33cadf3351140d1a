#pragma once
// Linking samples, G-code lines and points in space (the paper's locate functions).
#include <cstddef>
#include <cstdint>
#include <optional>

#include "isurface/core/trajectory.h"

namespace isurface {

class BiipReader;

// The first sample produced by a G-code line (as the paper's locate does), if any.
std::optional<std::size_t> firstSampleOfLine(const Trajectory& samples, std::uint32_t line);

// The sample nearest to a point (commanded positions), if there are samples.
std::optional<std::size_t> nearestSample(const Trajectory& samples, const Vec3& point);

// The same, read in place from a dump (nothing is loaded): answers fast on any size. Without
// a line channel no sample has a line.
std::optional<std::size_t> firstSampleOfLine(const BiipReader& reader, std::uint32_t line);
std::optional<std::size_t> nearestSample(const BiipReader& reader, const Vec3& point);

// Motion parameters at one sample, from the samples around it with kinematics.h's formulas
// (the values deriveKinematics gives for the whole trajectory).
struct SampleMotion {
  double speed = 0;           // mm/min, path
  double accel = 0;           // mm/s^2, tangential (signed)
  double accelMagnitude = 0;  // mm/s^2
  double jerk = 0;            // mm/s^3, |j|
  Vec3 velocity = Vec3::Zero();      // mm/min, per axis
  Vec3 acceleration = Vec3::Zero();  // mm/s^2, per axis
  Vec3 jerkAxes = Vec3::Zero();      // mm/s^3, per axis
};

// `sample` must be below the number of samples.
SampleMotion motionAtSample(const Trajectory& samples, std::size_t sample);
SampleMotion motionAtSample(const BiipReader& reader, std::size_t sample);

}  // namespace isurface
