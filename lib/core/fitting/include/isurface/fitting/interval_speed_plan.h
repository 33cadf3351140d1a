#pragma once
// One planned feed per constant speed interval (step 7 of the constant speed interval method)
// and the jerk-limited (S-curve) change of speed between neighbouring intervals.
//
// The interval's feed is the smallest of
//   - the programmed feed F,
//   - sqrt(a_n * rho_avg): centripetal acceleration v^2 / rho within a_n,
//   - cbrt(j_n * rho_avg^2): centripetal jerk v^3 / rho^2 within j_n,
// with rho_avg = 1 / average curvature of the interval (a straight interval has no curvature
// limit) and a_n, j_n half the smallest axis acceleration and jerk: the other half is left for
// the tangential speed changes between intervals, so that both together stay within any axis.
#include <vector>

#include "isurface/fitting/constant_speed_intervals.h"
#include "isurface/machine/machine.h"

namespace isurface {

// The share of the smallest axis acceleration and jerk given to the curvature limits; the
// transitions between intervals use the same share.
constexpr double kIntervalLimitShare = 0.5;

struct IntervalLimits {
  double acceleration = 0;  // mm/s^2
  double jerk = 0;          // mm/s^3; 0 = not limited
};

// a_n and j_n of a machine (the share above of its smallest axis limits).
IntervalLimits intervalLimits(const Machine& machine);

// Time (s) of a jerk-limited change of speed by dv (mm/s) with acceleration a and jerk j:
// |dv| / a + a / j when |dv| >= a^2 / j (the acceleration reaches a), else 2 sqrt(|dv| / j).
// Without a jerk limit (j = 0): |dv| / a.
double sCurveTransitionTime(double dv, double acceleration, double jerk);
// Distance (mm) covered during that change, from speed v0 to v1 (mm/s): the profile is
// symmetric in time, so the mean speed is (v0 + v1) / 2.
double sCurveTransitionDistance(double v0, double v1, double acceleration, double jerk);

// The feed limit of one interval, mm/min.
double intervalFeed(double programmedFeedMmMin, double averageCurvature, const IntervalLimits& limits);

struct PlannedInterval {
  std::size_t first = 0, last = 0;  // indices into the section's points
  double lengthMm = 0;
  double averageCurvature = 0;      // mm^-1
  double plannedFeedMmMin = 0;     // mm/min, the interval's feed (intervalFeed())
  // The change from this interval's speed to the next one's (0 for the last interval).
  double transitionTimeS = 0;
  double transitionDistanceMm = 0;
};

// `programmedFeedsMmMin` holds one programmed feed per interval (mm/min).
std::vector<PlannedInterval> planIntervalSpeeds(const std::vector<ConstantSpeedInterval>& intervals,
                                                const std::vector<double>& programmedFeedsMmMin,
                                                const Machine& machine);
// The same programmed feed for every interval.
std::vector<PlannedInterval> planIntervalSpeeds(const std::vector<ConstantSpeedInterval>& intervals,
                                                double programmedFeedMmMin, const Machine& machine);

}  // namespace isurface
