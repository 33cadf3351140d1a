// Interval speed planning: curvature and jerk limits, S-curve transitions.
#include "isurface/fitting/interval_speed_plan.h"

#include <gtest/gtest.h>

#include <cmath>

namespace isurface {
namespace {

Machine testMachine() {
  Machine m;
  m.axes[0].maxAcceleration = 2000;
  m.axes[1].maxAcceleration = 1000;  // the smallest: a_n = 500 mm/s^2
  m.axes[2].maxAcceleration = 3000;
  m.axes[0].maxJerk = 50000;
  m.axes[1].maxJerk = 20000;  // the smallest: j_n = 10000 mm/s^3
  m.axes[2].maxJerk = 90000;
  return m;
}

TEST(intervalSpeedPlan, limitsAreHalfTheSmallestAxis) {
  const IntervalLimits l = intervalLimits(testMachine());
  EXPECT_DOUBLE_EQ(l.acceleration, 500);
  EXPECT_DOUBLE_EQ(l.jerk, 10000);
}

TEST(intervalSpeedPlan, feedOnHandComputedCases) {
  const IntervalLimits l{500, 10000};
  // Straight: the programmed feed.
  EXPECT_DOUBLE_EQ(intervalFeed(3000, 0, l), 3000);
  // rho = 2 mm: sqrt(500 * 2) = 31.62 mm/s, cbrt(10000 * 4) = 34.20 mm/s -> 1897.4 mm/min.
  EXPECT_NEAR(intervalFeed(6000, 0.5, l), std::sqrt(1000.0) * 60, 1e-9);
  // rho = 0.1 mm: sqrt(50) = 7.07, cbrt(100) = 4.64 mm/s: jerk limits -> 278.5 mm/min.
  EXPECT_NEAR(intervalFeed(6000, 10, l), std::cbrt(100.0) * 60, 1e-9);
  // rho = 100 mm: sqrt(50000) = 223.6 mm/s = 13416 mm/min > F 3000.
  EXPECT_DOUBLE_EQ(intervalFeed(3000, 0.01, l), 3000);
  // Without a jerk limit only acceleration counts.
  EXPECT_NEAR(intervalFeed(6000, 10, IntervalLimits{500, 0}), std::sqrt(50.0) * 60, 1e-9);
}

TEST(intervalSpeedPlan, sCurveTransitions) {
  // a = 500, j = 10000: a^2 / j = 25 mm/s. dv = 40 >= 25: 40/500 + 500/10000 = 0.13 s.
  EXPECT_NEAR(sCurveTransitionTime(40, 500, 10000), 0.13, 1e-12);
  EXPECT_NEAR(sCurveTransitionTime(-40, 500, 10000), 0.13, 1e-12);
  // dv = 16 < 25: 2 sqrt(16 / 10000) = 0.08 s.
  EXPECT_NEAR(sCurveTransitionTime(16, 500, 10000), 0.08, 1e-12);
  // At the switch both forms agree: 25/500 + 0.05 = 0.1 = 2 sqrt(25/10000).
  EXPECT_NEAR(sCurveTransitionTime(25, 500, 10000), 0.1, 1e-12);
  EXPECT_NEAR(sCurveTransitionTime(25 - 1e-9, 500, 10000), 0.1, 1e-6);
  EXPECT_NEAR(sCurveTransitionTime(40, 500, 0), 0.08, 1e-12);
  EXPECT_EQ(sCurveTransitionTime(0, 500, 10000), 0.0);
  // From 10 to 50 mm/s: 0.13 s at a mean of 30 mm/s -> 3.9 mm.
  EXPECT_NEAR(sCurveTransitionDistance(10, 50, 500, 10000), 3.9, 1e-12);
  EXPECT_NEAR(sCurveTransitionDistance(50, 10, 500, 10000), 3.9, 1e-12);
}

TEST(intervalSpeedPlan, plansEachIntervalAndTheChangesBetween) {
  const std::vector<ConstantSpeedInterval> intervals = {
      {0, 7, 0.0, 7.0}, {7, 11, 0.5, 6.2}, {11, 17, 0.0, 6.0}};
  const auto plan = planIntervalSpeeds(intervals, 3000, testMachine());
  ASSERT_EQ(plan.size(), 3u);
  EXPECT_DOUBLE_EQ(plan[0].plannedFeedMmMin, 3000);
  EXPECT_NEAR(plan[1].plannedFeedMmMin, std::sqrt(1000.0) * 60, 1e-9);
  EXPECT_DOUBLE_EQ(plan[2].plannedFeedMmMin, 3000);
  EXPECT_EQ(plan[1].first, 7u);
  EXPECT_EQ(plan[1].last, 11u);
  EXPECT_DOUBLE_EQ(plan[1].lengthMm, 6.2);
  // 50 mm/s -> 31.62 mm/s: dv = 18.38 < 25 -> T = 2 sqrt(18.38 / 10000).
  const double dv = 50 - std::sqrt(1000.0);
  EXPECT_NEAR(plan[0].transitionTimeS, 2 * std::sqrt(dv / 10000), 1e-12);
  EXPECT_NEAR(plan[0].transitionDistanceMm, 0.5 * (50 + std::sqrt(1000.0)) * plan[0].transitionTimeS, 1e-12);
  EXPECT_NEAR(plan[1].transitionTimeS, plan[0].transitionTimeS, 1e-12);
  EXPECT_EQ(plan[2].transitionTimeS, 0.0);
  EXPECT_EQ(plan[2].transitionDistanceMm, 0.0);
}

}  // namespace
}  // namespace isurface
