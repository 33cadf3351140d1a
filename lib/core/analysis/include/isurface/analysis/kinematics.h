#pragma once
// Motion parameters derived from sampled positions: velocity, acceleration and jerk, per axis
// and along the path.
//
// Differences (T = sample spacing; on a non-uniform time base the divided-difference forms that
// reduce to these on a regular grid):
//   velocity     (p[i+1] - p[i-1]) / 2T                      one-sided (-3p0 + 4p1 - p2) / 2T at ends
//   acceleration (p[i+1] - 2p[i] + p[i-1]) / T^2             one-sided (2p0 - 5p1 + 4p2 - p3) / T^2
//   jerk         mean of the two half-sample differences     (p[k+2] - 3p[k+1] + 3p[k] - p[k-1]) / T^3
//                on either side of the sample (so it sits at the sample, not half a cycle later);
//                the nearest one at the first and last two samples.
// Acceleration and jerk are exact for a cubic motion (constant jerk), the velocity for a
// quadratic one; on a non-uniform time base the acceleration is moved from the three nodes'
// mean time to the sample with the jerk, so it stays exact for a cubic.
// A non-finite position (or time) at sample m makes NaN only at m itself and at the samples
// whose stencil holds it: velocity and acceleration at m-1..m+1, jerk at m-2..m+2 (plus the
// first or last sample when m falls in their one-sided end stencils); nothing spreads further.
// Only the bad axis is affected; the path values (|v|, |a|, |j|) of those samples are NaN.
// With fewer than 2 samples the velocity is 0, fewer than 3 the acceleration, fewer than 4 the jerk.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace isurface {

struct Kinematics {
  std::vector<double> speed;           // mm/s, path speed |v|
  std::vector<double> accel;           // mm/s^2, tangential v.a/|v| (signed; 0 where |v| = 0)
  std::vector<double> accelMagnitude;  // mm/s^2, |a|
  std::vector<double> jerk;            // mm/s^3, |j|
  std::array<std::vector<double>, 3> axisVel;   // mm/s (empty unless asked for)
  std::array<std::vector<double>, 3> axisAcc;   // mm/s^2
  std::array<std::vector<double>, 3> axisJerk;  // mm/s^3
};

// x, y, z: n positions in mm. t: n sample times in s, or nullptr for a regular cycle.
// perAxis = false leaves axisVel/axisAcc/axisJerk empty (saves 9 arrays of n doubles).
Kinematics deriveKinematics(const double* x, const double* y, const double* z, const double* t, std::size_t n,
                            double cycleSeconds, bool perAxis = true);

// The same values at the samples at[0..count) only (in any order), from the whole arrays:
// out.speed[j] is sample at[j]'s. Each sample reads its own stencil, so a map of a few hundred
// thousand vertices over millions of samples derives no more than its vertices.
Kinematics deriveKinematicsAt(const double* x, const double* y, const double* z, const double* t, std::size_t n,
                              double cycleSeconds, const std::uint32_t* at, std::size_t count, bool perAxis = true);

struct KinematicsMaxima {
  double speed = 0;  // mm/s, max |v| (path) or |v_axis|
  double accel = 0;  // mm/s^2, max |a|
  double jerk = 0;   // mm/s^3, max |j|
};

// Maxima over the samples whose derived value is finite (NaN samples are skipped).
struct KinematicsSummary {
  std::size_t samples = 0;        // samples seen
  std::size_t finiteSamples = 0;  // samples whose velocity, acceleration and jerk are all finite
  double maxSpeed = 0, maxAccel = 0, maxJerk = 0;  // mm/s, mm/s^2, mm/s^3: path (vector magnitudes)
  std::size_t maxSpeedIndex = 0, maxAccelIndex = 0, maxJerkIndex = 0;  // where they occur
  std::array<KinematicsMaxima, 3> axis;                                // x, y, z
};

// Streams samples one at a time and keeps only the last seven: constant memory for any length.
// Gives exactly the values deriveKinematics() would.
class KinematicsAccumulator {
 public:
  // withTime: samples come with their time (push with t); else a regular cycle.
  explicit KinematicsAccumulator(double cycleSeconds, bool withTime = false);
  void push(double x, double y, double z) { push(x, y, z, 0.0); }
  void push(double x, double y, double z, double t);
  // Evaluates the last samples and returns the summary; the accumulator is spent afterwards.
  KinematicsSummary finish();

 private:
  void evaluate(std::size_t i, std::size_t n);

  bool withTime_;
  bool finished_ = false;
  std::size_t count_ = 0;
  double p_[8][3] = {};
  double t_[8] = {};
  double grid_[5] = {};  // reciprocal powers of the cycle
  KinematicsSummary summary_;
};

KinematicsSummary summarizeKinematics(const double* x, const double* y, const double* z, const double* t,
                                      std::size_t n, double cycleSeconds);

}  // namespace isurface
