// Derived velocity, acceleration and jerk against motions whose derivatives are known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "isurface/analysis/kinematics.h"
#include "test_support.h"

namespace isurface {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Cubic {
  double c0, c1, c2, c3;
  double p(double t) const { return c0 + t * (c1 + t * (c2 + t * c3)); }
  double v(double t) const { return c1 + t * (2 * c2 + t * 3 * c3); }
  double a(double t) const { return 2 * c2 + 6 * c3 * t; }
  double j() const { return 6 * c3; }
};

const Cubic kAxes[3] = {{1, 20, -3, 0.5}, {-4, -7, 2.5, -1.25}, {0.5, 1, 0.75, 2}};

struct Motion {
  std::vector<double> x, y, z, t;
};

Motion sampleCubic(std::size_t n, const std::vector<double>& times) {
  Motion m;
  m.t = times;
  for (std::size_t i = 0; i < n; ++i) {
    m.x.push_back(kAxes[0].p(times[i]));
    m.y.push_back(kAxes[1].p(times[i]));
    m.z.push_back(kAxes[2].p(times[i]));
  }
  return m;
}

std::vector<double> regularTimes(std::size_t n, double T) {
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = double(i) * T;
  return t;
}

TEST(kinematics, CubicMotionOnARegularGrid) {
  const double T = 0.01;
  const std::size_t n = 200;
  const auto times = regularTimes(n, T);
  const Motion m = sampleCubic(n, times);
  const Kinematics k = deriveKinematics(m.x.data(), m.y.data(), m.z.data(), nullptr, n, T);
  ASSERT_EQ(k.speed.size(), n);
  for (int ax = 0; ax < 3; ++ax) {
    const Cubic& c = kAxes[ax];
    for (std::size_t i = 0; i < n; ++i) {
      const double t = times[i];
      // Acceleration and jerk: exact (rounding only), ends included.
      EXPECT_NEAR(k.axisAcc[ax][i], c.a(t), 1e-8) << ax << " " << i;
      EXPECT_NEAR(k.axisJerk[ax][i], c.j(), 1e-6) << ax << " " << i;
      // Velocity: the central difference is exact for quadratics; for a cubic it is off by
      // exactly c3 T^2 inside and -2 c3 T^2 at the one-sided ends.
      const double bias = (i == 0 || i == n - 1) ? -2 * c.c3 * T * T : c.c3 * T * T;
      EXPECT_NEAR(k.axisVel[ax][i], c.v(t) + bias, 1e-9) << ax << " " << i;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double vx = k.axisVel[0][i], vy = k.axisVel[1][i], vz = k.axisVel[2][i];
    EXPECT_NEAR(k.speed[i], std::sqrt(vx * vx + vy * vy + vz * vz), 1e-9);
    const double ax = k.axisAcc[0][i], ay = k.axisAcc[1][i], az = k.axisAcc[2][i];
    EXPECT_NEAR(k.accelMagnitude[i], std::sqrt(ax * ax + ay * ay + az * az), 1e-9);
    EXPECT_NEAR(k.accel[i], (vx * ax + vy * ay + vz * az) / std::sqrt(vx * vx + vy * vy + vz * vz), 1e-9);
    EXPECT_NEAR(k.jerk[i], std::sqrt(3.0 * 3.0 + 7.5 * 7.5 + 12.0 * 12.0), 1e-6);
  }
}

TEST(kinematics, CircleAtConstantSpeed) {
  const double T = 0.001, R = 50, v = 50;  // 3000 mm/min, omega = 1 rad/s
  const double w = v / R;
  const std::size_t n = 8000;  // more than a full turn
  std::vector<double> x(n), y(n), z(n, 5.0);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = 10 + R * std::cos(w * i * T);
    y[i] = -3 + R * std::sin(w * i * T);
  }
  const Kinematics k = deriveKinematics(x.data(), y.data(), z.data(), nullptr, n, T);
  for (std::size_t i = 0; i < n; ++i) {
    const bool end = i == 0 || i == n - 1;
    const double tol = end ? 1e-5 : 1e-6;
    EXPECT_NEAR(k.speed[i] / v, 1.0, tol) << i;  // mm/s
    EXPECT_NEAR(k.accelMagnitude[i] / (v * v / R), 1.0, tol) << i;
    EXPECT_NEAR(k.accel[i] / (v * v / R), 0.0, 1e-5) << i;  // no tangential component
    EXPECT_NEAR(k.jerk[i] / (v * v * v / (R * R)), 1.0, 1e-2) << i;  // T^3 amplifies rounding
    EXPECT_EQ(k.axisVel[2][i], 0.0);
  }
  const KinematicsSummary s = summarizeKinematics(x.data(), y.data(), z.data(), nullptr, n, T);
  EXPECT_NEAR(s.maxSpeed, 50, 50 * 1e-5);  // mm/s
  EXPECT_NEAR(s.maxAccel, 50, 50 * 1e-5);
  EXPECT_NEAR(s.axis[0].speed, 50, 50 * 1e-5);
  EXPECT_NEAR(s.axis[1].accel, 50, 50 * 1e-5);
  EXPECT_EQ(s.axis[2].speed, 0.0);
}

TEST(kinematics, IrregularTimes) {
  const double T = 0.01;
  const std::size_t n = 150;
  std::vector<double> times(n);
  for (std::size_t i = 0; i < n; ++i) times[i] = 3.0 + i * T + 0.3 * T * std::sin(1.7 * i);
  const Motion m = sampleCubic(n, times);
  const Kinematics k = deriveKinematics(m.x.data(), m.y.data(), m.z.data(), times.data(), n, T);
  for (int ax = 0; ax < 3; ++ax) {
    const Cubic& c = kAxes[ax];
    for (std::size_t i = 0; i < n; ++i) {
      const double t = times[i];
      EXPECT_NEAR(k.axisAcc[ax][i], c.a(t), 1e-6) << ax << " " << i;
      EXPECT_NEAR(k.axisJerk[ax][i], c.j(), 1e-4) << ax << " " << i;
      if (i > 0 && i + 1 < n) {
        // The quadratic through three samples misses a cubic's slope by c3 h1 h2.
        const double h1 = times[i] - times[i - 1], h2 = times[i + 1] - times[i];
        EXPECT_NEAR(k.axisVel[ax][i], c.v(t) + c.c3 * h1 * h2, 1e-7) << ax << " " << i;
      }
    }
  }
  // A quadratic motion: velocity exact everywhere, ends included.
  std::vector<double> x(n), y(n), z(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = times[i];
    x[i] = 2 + 5 * t - 4 * t * t;
    y[i] = -1 + 0.5 * t * t;
    z[i] = 7;
  }
  const Kinematics q = deriveKinematics(x.data(), y.data(), z.data(), times.data(), n, T);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(q.axisVel[0][i], 5 - 8 * times[i], 1e-7) << i;
    EXPECT_NEAR(q.axisVel[1][i], times[i], 1e-7) << i;
    EXPECT_NEAR(q.axisAcc[0][i], -8, 1e-6) << i;
    EXPECT_NEAR(q.axisJerk[0][i], 0, 1e-4) << i;
  }
}

TEST(kinematics, ExplicitRegularTimesMatchTheCycle) {
  const double T = 0.002;
  const std::size_t n = 300;
  const auto times = regularTimes(n, T);
  const Motion m = sampleCubic(n, times);
  const Kinematics a = deriveKinematics(m.x.data(), m.y.data(), m.z.data(), nullptr, n, T);
  const Kinematics b = deriveKinematics(m.x.data(), m.y.data(), m.z.data(), times.data(), n, T);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(a.speed[i], b.speed[i], 1e-7 * a.speed[i]) << i;
    EXPECT_NEAR(a.accelMagnitude[i], b.accelMagnitude[i], 1e-6 * a.accelMagnitude[i] + 1e-9) << i;
    EXPECT_NEAR(a.jerk[i], b.jerk[i], 1e-3) << i;
  }
}

// Which samples a non-finite sample m may reach: velocity and acceleration at m-1..m+1 and
// jerk at m-2..m+2, plus the one-sided stencils of the first and last samples.
struct Reach {
  bool speed, accel, jerk;
};
Reach reach(std::size_t i, std::size_t m, std::size_t n, bool regular) {
  const auto within = [&](std::size_t r) { return i + r >= m && i <= m + r; };
  const bool first = i == 0, last = i == n - 1;
  Reach r;
  r.speed = within(1) || (first && m == 2) || (last && m == n - 3);
  // On a regular grid the end acceleration is a 4-point formula; with times it is the 3-point
  // one, corrected by the jerk only when that is finite.
  r.accel = r.speed || (regular && ((first && m == 3) || (last && m == n - 4)));
  r.jerk = within(2) || (i < 2 && m <= 3) || (i + 2 >= n && m + 4 >= n);
  return r;
}

void checkIsolation(const double* t, std::size_t m, double bad) {
  const std::size_t n = 60;
  std::vector<double> x(n), y(n), z(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double ti = t ? t[i] : i * 0.001;
    x[i] = 100 * ti * ti;
    y[i] = 30 * ti;
    z[i] = -ti * ti * ti;
  }
  y[m] = bad;
  const Kinematics k = deriveKinematics(x.data(), y.data(), z.data(), t, n, 0.001);
  for (std::size_t i = 0; i < n; ++i) {
    const Reach r = reach(i, m, n, t == nullptr);
    EXPECT_EQ(!std::isfinite(k.speed[i]), r.speed) << "speed " << i << ", bad " << m;
    EXPECT_EQ(!std::isfinite(k.accelMagnitude[i]), r.accel) << "accel " << i << ", bad " << m;
    EXPECT_EQ(!std::isfinite(k.accel[i]), r.speed || r.accel) << "tangential " << i << ", bad " << m;
    EXPECT_EQ(!std::isfinite(k.jerk[i]), r.jerk) << "jerk " << i << ", bad " << m;
    EXPECT_TRUE(std::isfinite(k.axisVel[0][i]));  // other axes are untouched
    EXPECT_TRUE(std::isfinite(k.axisAcc[0][i]));
    EXPECT_TRUE(std::isfinite(k.axisJerk[2][i]));
  }
}

TEST(kinematics, NonFiniteSamplesStayLocal) {
  for (std::size_t m = 0; m < 60; ++m) checkIsolation(nullptr, m, kNaN);
  for (std::size_t m : {0u, 3u, 30u, 59u}) checkIsolation(nullptr, m, -HUGE_VAL);
}

TEST(kinematics, NonFiniteSamplesStayLocalWithIrregularTimes) {
  std::vector<double> t(60);
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = i * 0.001 + 0.0002 * std::cos(double(i));
  for (std::size_t m = 0; m < 60; ++m) checkIsolation(t.data(), m, kNaN);
  checkIsolation(t.data(), 31, HUGE_VAL);
  // A bad time behaves like a bad position.
  std::vector<double> x(60, 1.0), tt = t;
  tt[20] = kNaN;
  const Kinematics k = deriveKinematics(x.data(), x.data(), x.data(), tt.data(), 60, 0.001);
  EXPECT_TRUE(std::isnan(k.speed[20]));
  EXPECT_FALSE(std::isnan(k.speed[17]));
  EXPECT_FALSE(std::isnan(k.jerk[24]));
}

TEST(kinematics, ShortSeries) {
  const double x[] = {0, 1, 3, 6}, y[] = {0, 0, 0, 0}, z[] = {0, 0, 0, 0};
  EXPECT_TRUE(deriveKinematics(x, y, z, nullptr, 0, 0.1).speed.empty());
  const Kinematics one = deriveKinematics(x, y, z, nullptr, 1, 0.1);
  EXPECT_EQ(one.speed, std::vector<double>{0.0});
  EXPECT_EQ(one.jerk, std::vector<double>{0.0});
  const Kinematics two = deriveKinematics(x, y, z, nullptr, 2, 0.1);
  EXPECT_NEAR(two.speed[0], 10, 1e-9);  // mm/s: 1 mm in 0.1 s
  EXPECT_NEAR(two.speed[1], 10, 1e-9);
  EXPECT_EQ(two.accelMagnitude[1], 0.0);
  const Kinematics three = deriveKinematics(x, y, z, nullptr, 3, 0.1);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(three.axisAcc[0][i], 100, 1e-9);  // (3 - 2 + 0) / 0.01
    EXPECT_EQ(three.jerk[i], 0.0);
  }
  EXPECT_NEAR(three.axisVel[0][1], 15, 1e-9);
  const Kinematics four = deriveKinematics(x, y, z, nullptr, 4, 0.1);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(four.axisJerk[0][i], 0, 1e-6);  // x is quadratic
  const double cubic[] = {0, 1, 8, 27};
  const Kinematics c = deriveKinematics(cubic, y, z, nullptr, 4, 1.0);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(c.axisJerk[0][i], 6, 1e-12);
    EXPECT_NEAR(c.axisAcc[0][i], 6.0 * i, 1e-12);
  }
}

TEST(kinematics, TangentialAccelerationHasTheSignOfTheSpeedChange) {
  const std::size_t n = 100;
  const double T = 0.001;
  std::vector<double> x(n), y(n), z(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = i * T;
    x[i] = 0.6 * (10 * t + 250 * t * t);  // speeding up at 500 mm/s^2 along (0.6, 0.8)
    y[i] = 0.8 * (10 * t + 250 * t * t);
  }
  const Kinematics up = deriveKinematics(x.data(), y.data(), z.data(), nullptr, n, T);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(up.accel[i], 500, 1e-6) << i;
  std::reverse(x.begin(), x.end());
  std::reverse(y.begin(), y.end());
  const Kinematics down = deriveKinematics(x.data(), y.data(), z.data(), nullptr, n, T);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(down.accel[i], -500, 1e-6) << i;
}

TEST(kinematics, StreamingSummaryMatchesTheArrays) {
  for (bool withTime : {false, true}) {
    for (std::size_t n : {0u, 1u, 2u, 3u, 4u, 5u, 7u, 8u, 9u, 1000u}) {
      std::vector<double> x(n), y(n), z(n), t(n);
      for (std::size_t i = 0; i < n; ++i) {
        t[i] = 1 + i * 0.001 + (withTime ? 0.0003 * std::sin(3.0 * i) : 0.0);
        x[i] = 20 * std::sin(3 * t[i]) + 0.001 * std::sin(91.0 * i);
        y[i] = 5 * std::cos(7 * t[i]);
        z[i] = t[i] * t[i];
      }
      if (n > 500) x[500] = kNaN;
      const double* tp = withTime ? t.data() : nullptr;
      const Kinematics k = deriveKinematics(x.data(), y.data(), z.data(), tp, n, 0.001);
      KinematicsAccumulator acc(0.001, withTime);
      for (std::size_t i = 0; i < n; ++i) acc.push(x[i], y[i], z[i], t[i]);
      const KinematicsSummary s = acc.finish();
      const KinematicsSummary direct = summarizeKinematics(x.data(), y.data(), z.data(), tp, n, 0.001);
      double maxSpeed = 0, maxAccel = 0, maxJerk = 0, maxAxisJerk = 0;
      std::size_t finite = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (k.speed[i] > maxSpeed) maxSpeed = k.speed[i];
        if (k.accelMagnitude[i] > maxAccel) maxAccel = k.accelMagnitude[i];
        if (k.jerk[i] > maxJerk) maxJerk = k.jerk[i];
        if (std::fabs(k.axisJerk[1][i]) > maxAxisJerk) maxAxisJerk = std::fabs(k.axisJerk[1][i]);
        finite += std::isfinite(k.speed[i]) && std::isfinite(k.accelMagnitude[i]) && std::isfinite(k.jerk[i]);
      }
      for (const KinematicsSummary& sum : {s, direct}) {
        EXPECT_EQ(sum.samples, n);
        EXPECT_EQ(sum.finiteSamples, finite);
        EXPECT_EQ(sum.maxSpeed, maxSpeed) << n << withTime;
        EXPECT_EQ(sum.maxAccel, maxAccel) << n << withTime;
        EXPECT_EQ(sum.maxJerk, maxJerk) << n << withTime;
        EXPECT_EQ(sum.axis[1].jerk, maxAxisJerk) << n << withTime;
        if (n > 0) {
          EXPECT_EQ(k.speed[sum.maxSpeedIndex], maxSpeed);
        }
      }
    }
  }
}

// An infinite position (a dump with x = inf, or 1e300) is left out of the maxima, as a NaN is:
// the summary's maxima are those of the finite samples, not inf.
TEST(kinematics, AnInfiniteSampleIsLeftOutOfTheMaxima) {
  for (const double bad : {HUGE_VAL, -HUGE_VAL, 1e300}) {
    const std::size_t n = 200;
    std::vector<double> x(n), y(n), z(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = 0.05 * i, y[i] = 0.001 * i * i * 0.001, z[i] = 0;
    const KinematicsSummary clean = summarizeKinematics(x.data(), y.data(), z.data(), nullptr, n, 0.001);
    x[100] = bad;
    const KinematicsSummary s = summarizeKinematics(x.data(), y.data(), z.data(), nullptr, n, 0.001);
    EXPECT_TRUE(std::isfinite(s.maxSpeed)) << bad;
    EXPECT_TRUE(std::isfinite(s.maxAccel)) << bad;
    EXPECT_TRUE(std::isfinite(s.maxJerk)) << bad;
    EXPECT_TRUE(std::isfinite(s.axis[0].speed) && std::isfinite(s.axis[0].accel) && std::isfinite(s.axis[0].jerk)) << bad;
    EXPECT_NEAR(s.maxSpeed, clean.maxSpeed, 1e-9 * clean.maxSpeed) << bad;
    EXPECT_LT(s.finiteSamples, clean.finiteSamples) << bad;
  }
}

// A map derives only at its vertices' samples; every value must be the one of the whole
// derivation, bit for bit: at the ends (one-sided stencils), beside a bad sample, in any order.
TEST(kinematics, ValuesAtChosenSamplesAreThoseOfTheWholeArrays) {
  for (bool withTime : {false, true}) {
    for (std::size_t n : {1u, 2u, 3u, 4u, 5u, 9u, 1000u}) {
      std::vector<double> x(n), y(n), z(n), t(n);
      for (std::size_t i = 0; i < n; ++i) {
        t[i] = 2 + i * 0.001 + (withTime ? 0.0004 * std::cos(5.0 * i) : 0.0);
        x[i] = 15 * std::cos(2 * t[i]) + 0.002 * std::sin(37.0 * i);
        y[i] = 3 * std::sin(11 * t[i]);
        z[i] = -t[i] * t[i] * t[i];
      }
      if (n > 600) y[600] = kNaN;
      std::vector<std::uint32_t> at;
      for (std::size_t i = n; i-- > 0;)
        if (i % 7 == 0 || i < 3 || i + 3 > n || (i >= 596 && i <= 604)) at.push_back(std::uint32_t(i));
      at.push_back(at.front());  // a sample asked for twice
      const double* tp = withTime ? t.data() : nullptr;
      for (bool perAxis : {false, true}) {
        const Kinematics all = deriveKinematics(x.data(), y.data(), z.data(), tp, n, 0.001, perAxis);
        const Kinematics some =
            deriveKinematicsAt(x.data(), y.data(), z.data(), tp, n, 0.001, at.data(), at.size(), perAxis);
        ASSERT_EQ(some.speed.size(), at.size());
        ASSERT_EQ(some.axisJerk[2].size(), perAxis ? at.size() : 0u);
        // Compared as bits: NaN where the whole derivation has NaN, the same double elsewhere.
        const auto same = [](double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; };
        for (std::size_t j = 0; j < at.size(); ++j) {
          const std::size_t i = at[j];
          EXPECT_TRUE(same(some.speed[j], all.speed[i])) << n << " " << i;
          EXPECT_TRUE(same(some.accel[j], all.accel[i])) << n << " " << i;
          EXPECT_TRUE(same(some.accelMagnitude[j], all.accelMagnitude[i])) << n << " " << i;
          EXPECT_TRUE(same(some.jerk[j], all.jerk[i])) << n << " " << i;
          if (!perAxis) continue;
          for (int ax = 0; ax < 3; ++ax) {
            EXPECT_TRUE(same(some.axisVel[ax][j], all.axisVel[ax][i])) << n << " " << i;
            EXPECT_TRUE(same(some.axisAcc[ax][j], all.axisAcc[ax][i])) << n << " " << i;
            EXPECT_TRUE(same(some.axisJerk[ax][j], all.axisJerk[ax][i])) << n << " " << i;
          }
        }
        if (n > 600) {
          EXPECT_TRUE(std::isnan(some.jerk[std::find(at.begin(), at.end(), 600u) - at.begin()]));
        }
      }
    }
  }
}

TEST(kinematics, PathOnlyLeavesAxisArraysEmpty) {
  const double x[] = {0, 1, 2, 3, 4}, y[] = {0, 0, 0, 0, 0};
  const Kinematics k = deriveKinematics(x, y, y, nullptr, 5, 0.5, false);
  EXPECT_EQ(k.speed.size(), 5u);
  EXPECT_TRUE(k.axisVel[0].empty());
  EXPECT_NEAR(k.speed[2], 2, 1e-12);  // mm/s
}

}  // namespace
}  // namespace isurface
