#include "isurface/fitting/interval_speed_plan.h"

#include <algorithm>
#include <cmath>

#include "isurface/base/units.h"

namespace isurface {

IntervalLimits intervalLimits(const Machine& machine) {
  IntervalLimits l;
  l.acceleration = std::min({machine.axes[0].maxAcceleration, machine.axes[1].maxAcceleration,
                             machine.axes[2].maxAcceleration}) * kIntervalLimitShare;
  l.jerk = machine.jerkLimited() ? std::min({machine.axes[0].maxJerk, machine.axes[1].maxJerk,
                                             machine.axes[2].maxJerk}) * kIntervalLimitShare
                                 : 0.0;
  return l;
}

double sCurveTransitionTime(double dv, double a, double j) {
  dv = std::abs(dv);
  if (dv == 0 || !(a > 0)) return 0.0;
  if (!(j > 0)) return dv / a;
  if (dv >= a * a / j) return dv / a + a / j;
  return 2.0 * std::sqrt(dv / j);
}

double sCurveTransitionDistance(double v0, double v1, double a, double j) {
  return 0.5 * (v0 + v1) * sCurveTransitionTime(v1 - v0, a, j);
}

double intervalFeed(double programmedFeedMmMin, double averageCurvature, const IntervalLimits& limits) {
  double v = mmPerMinToMmPerS(programmedFeedMmMin);  // mm/s
  if (averageCurvature > kZeroCurvature) {
    const double rho = 1.0 / averageCurvature;
    v = std::min(v, std::sqrt(limits.acceleration * rho));
    if (limits.jerk > 0) v = std::min(v, std::cbrt(limits.jerk * rho * rho));
  }
  return mmPerSToMmPerMin(v);
}

std::vector<PlannedInterval> planIntervalSpeeds(const std::vector<ConstantSpeedInterval>& intervals,
                                                double programmedFeedMmMin, const Machine& machine) {
  return planIntervalSpeeds(intervals, std::vector<double>(intervals.size(), programmedFeedMmMin), machine);
}

std::vector<PlannedInterval> planIntervalSpeeds(const std::vector<ConstantSpeedInterval>& intervals,
                                                const std::vector<double>& programmedFeedsMmMin,
                                                const Machine& machine) {
  const IntervalLimits limits = intervalLimits(machine);
  std::vector<PlannedInterval> out;
  for (std::size_t k = 0; k < intervals.size(); ++k) {
    const ConstantSpeedInterval& i = intervals[k];
    const double programmedFeedMmMin = k < programmedFeedsMmMin.size() ? programmedFeedsMmMin[k] : 0.0;
    PlannedInterval p;
    p.first = i.first;
    p.last = i.last;
    p.lengthMm = i.length;
    p.averageCurvature = i.averageCurvature;
    p.plannedFeedMmMin = intervalFeed(programmedFeedMmMin, i.averageCurvature, limits);
    out.push_back(p);
  }
  for (std::size_t k = 0; k + 1 < out.size(); ++k) {
    const double v0 = mmPerMinToMmPerS(out[k].plannedFeedMmMin);
    const double v1 = mmPerMinToMmPerS(out[k + 1].plannedFeedMmMin);
    out[k].transitionTimeS = sCurveTransitionTime(v1 - v0, limits.acceleration, limits.jerk);
    out[k].transitionDistanceMm = sCurveTransitionDistance(v0, v1, limits.acceleration, limits.jerk);
  }
  return out;
}

}  // namespace isurface
