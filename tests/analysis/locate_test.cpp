// Locating samples by line, index and point in memory, and the motion at a sample.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "isurface/analysis/kinematics.h"
#include "isurface/analysis/locate.h"

using namespace isurface;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(locate, FirstSampleOfLineInMemory) {
  Trajectory t;
  t.hasLine = true;
  t.line = {0, 0, 3, 3, 4, 3, 5};
  t.x.assign(7, 0);
  t.y.assign(7, 0);
  t.z.assign(7, 0);
  EXPECT_EQ(firstSampleOfLine(t, 3), 2u);
  EXPECT_EQ(firstSampleOfLine(t, 5), 6u);
  EXPECT_FALSE(firstSampleOfLine(t, 9).has_value());
  EXPECT_EQ(firstSampleOfLine(t, 0), 0u);
  t.hasLine = false;
  t.line.assign(7, 0);
  EXPECT_FALSE(firstSampleOfLine(t, 0).has_value());
}

TEST(locate, NearestSampleIsExact) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-10, 10);
  Trajectory t;
  for (int i = 0; i < 5000; ++i) {
    t.x.push_back(u(random));
    t.y.push_back(u(random));
    t.z.push_back(u(random));
  }
  t.x[17] = kNaN;  // never nearest
  EXPECT_FALSE(nearestSample(Trajectory{}, Vec3::Zero()).has_value());
  for (int q = 0; q < 50; ++q) {
    const Vec3 p(u(random), u(random), u(random));
    std::size_t best = 0;
    double bestD = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double d = (t.commanded(i) - p).squaredNorm();
      if (d < bestD) bestD = d, best = i;
    }
    EXPECT_EQ(nearestSample(t, p), best);
  }
  EXPECT_EQ(nearestSample(t, Vec3(t.x[1234], t.y[1234], t.z[1234])), 1234u);
}

TEST(locate, MotionWithAnIrregularTimeBase) {
  Trajectory t;
  t.cycle = 0.001;
  for (int i = 0; i < 40; ++i) {
    const double s = 0.001 * i + (i % 3 == 1 ? 0.0002 : 0.0);
    t.time.push_back(s);
    t.x.push_back(s * s * s);
    t.y.push_back(2 * s);
    t.z.push_back(0);
  }
  t.irregularTime = true;
  const Kinematics k = deriveKinematics(t.x.data(), t.y.data(), t.z.data(), t.time.data(), t.size(), t.cycle, true);
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_EQ(motionAtSample(t, i).jerk, k.jerk[i]) << i;
}

}  // namespace
