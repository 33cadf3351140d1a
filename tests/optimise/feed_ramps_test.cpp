// One feed per move with the changes between intervals spread into ramps: never faster than the
// interval, on the old path, the same whichever way the pass runs, bends within the normal
// acceleration asked for.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>
#include "isurface/base/units.h"
#include "isurface/optimise/feed_ramps.h"

using namespace isurface;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A plane of 20 mm (one move), a fillet of radius 5 mm over 30 degrees (moves of 0.05 mm), a
// slope of 20 mm (one move), along X; three intervals at F2500, F1200, F2500.
PassFeeds planeFilletSlope() {
  PassFeeds pass;
  pass.points = {Vec3(0, 0, 0), Vec3(20, 0, 0)};
  const double radius = 5, sweep = kPi / 6;
  const int pieces = static_cast<int>(std::ceil(radius * sweep / 0.05));
  for (int k = 1; k <= pieces; ++k) {
    const double a = sweep * k / pieces;
    pass.points.push_back(Vec3(20 + radius * std::sin(a), 0, radius * (1 - std::cos(a))));
  }
  pass.intervalEnd = {1, pass.points.size() - 1};
  const Vec3 end = pass.points.back(), direction(std::cos(sweep), 0, std::sin(sweep));
  pass.points.push_back(end + 20 * direction);
  pass.intervalEnd.push_back(pass.points.size() - 1);
  pass.feeds = {2500, 1200, 2500};
  pass.sourceLines.assign(pass.points.size(), 7);
  return pass;
}

PassFeeds reversed(PassFeeds pass) {
  std::reverse(pass.points.begin(), pass.points.end());
  const std::size_t last = pass.points.size() - 1;
  std::vector<std::size_t> ends;
  for (auto it = pass.intervalEnd.rbegin() + 1; it != pass.intervalEnd.rend(); ++it) ends.push_back(last - *it);
  ends.push_back(last);
  pass.intervalEnd = ends;
  std::reverse(pass.feeds.begin(), pass.feeds.end());
  return pass;
}

// The feed (mm/min) of the move that holds the point at x (mm) on the pass.
double feedAt(const FeedPerMove& m, double x) {
  for (std::size_t k = 0; k + 1 < m.points.size(); ++k) {
    const double lo = std::min(m.points[k].x(), m.points[k + 1].x()), hi = std::max(m.points[k].x(), m.points[k + 1].x());
    if (x >= lo && x <= hi) return m.feeds[k];
  }
  return NAN;
}

double distanceToPolyline(const Vec3& p, const std::vector<Vec3>& line) {
  double best = INFINITY;
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const Vec3 d = line[k + 1] - line[k];
    const double t = std::clamp((p - line[k]).dot(d) / d.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (line[k] + t * d - p).norm());
  }
  return best;
}

}  // namespace

TEST(feedRamps, WithoutRampsEachMoveRunsAtItsIntervalsFeed) {
  const PassFeeds pass = planeFilletSlope();
  const FeedPerMove m = feedPerMove(pass, {});
  ASSERT_EQ(m.points.size(), pass.points.size());
  EXPECT_EQ(m.feeds.front(), 2500);
  EXPECT_EQ(m.feeds[1], 1200);
  EXPECT_EQ(m.feeds.back(), 2500);
}

TEST(feedRamps, ARampStaysOnThePathBelowTheIntervalFeedsAndWithinItsAcceleration) {
  const PassFeeds pass = planeFilletSlope();
  RampOptions options;
  options.programmedFeed = 2500;  // ramps in steps of 25 mm/min
  options.rampAcceleration = 100;
  const FeedPerMove m = feedPerMove(pass, options);
  ASSERT_EQ(m.feeds.size() + 1, m.points.size());
  EXPECT_GT(m.points.size(), pass.points.size() + 20);  // the long moves are cut into a ramp
  for (const Vec3& p : m.points) EXPECT_LT(distanceToPolyline(p, pass.points), 1e-9);
  for (const Vec3& p : pass.points) EXPECT_LT(distanceToPolyline(p, m.points), 1e-9);
  for (std::size_t k = 0; k < m.feeds.size(); ++k) {
    const double x = 0.5 * (m.points[k].x() + m.points[k + 1].x());
    EXPECT_LE(m.feeds[k], x < 20 || x > 22.5 ? 2500 : 1200) << "move " << k;
    EXPECT_EQ(m.sourceLines[k + 1], 7u);
  }
  // From one move to the next the feed changes by a step at most, and no faster than the ramp's
  // acceleration allows over the move before (v^2 = v0^2 + 2 a s, one step of rounding).
  for (std::size_t k = 1; k < m.feeds.size(); ++k) {
    const double v0 = mmPerMinToMmPerS(m.feeds[k - 1]), v1 = mmPerMinToMmPerS(m.feeds[k]);
    const double length = (m.points[k] - m.points[k - 1]).norm();
    const double reachable = std::sqrt(std::min(v0, v1) * std::min(v0, v1) + 2 * 100 * length);
    EXPECT_LE(std::abs(m.feeds[k] - m.feeds[k - 1]), 25.0 + 1e-9) << "move " << k;
    EXPECT_LE(std::max(v0, v1), reachable + mmPerMinToMmPerS(25.0) + 1e-9) << "move " << k;
  }
  // The ramp down ends where the fillet starts: the fillet runs at its own feed.
  EXPECT_EQ(feedAt(m, 21.0), 1200);
  EXPECT_LT(feedAt(m, 19.9), 1300);
  EXPECT_EQ(feedAt(m, 5.0), 2500);
}

TEST(feedRamps, APassRunTheOtherWayGetsTheSameFeedsWhereItIs) {
  RampOptions options;
  options.programmedFeed = 2500;
  options.rampAcceleration = 150;
  options.normalAccelerationLimit = 60;
  const FeedPerMove forward = feedPerMove(planeFilletSlope(), options);
  const FeedPerMove backward = feedPerMove(reversed(planeFilletSlope()), options);
  for (double x = 0.25; x < 38; x += 0.05) EXPECT_EQ(feedAt(forward, x), feedAt(backward, x)) << "x " << x;
}

TEST(feedRamps, BendsRunWithinTheNormalAccelerationAskedFor) {
  RampOptions options;
  options.programmedFeed = 2500;
  options.normalAccelerationLimit = 40;  // mm/s^2: sqrt(40 * 5) = 14.1 mm/s = 849 mm/min on the fillet
  options.rampAcceleration = 100;
  const FeedPerMove m = feedPerMove(planeFilletSlope(), options);
  const double expected = mmPerSToMmPerMin(std::sqrt(40.0 * 5.0));
  for (const double x : {20.6, 21.0, 21.5, 22.0}) EXPECT_NEAR(feedAt(m, x), expected, 0.01 * expected) << "x " << x;
  // The plane keeps its feed and slows into the bend: v^2 = v_bend^2 + 2 a s reaches F2500
  // 7.7 mm before it.
  EXPECT_EQ(feedAt(m, 5.0), 2500);
  EXPECT_EQ(feedAt(m, 11.0), 2500);
  EXPECT_LT(feedAt(m, 19.0), 1500);
  options.normalAccelerationLimit = 1e6;  // a limit above what the interval asks changes nothing
  options.rampAcceleration = 100;
  EXPECT_EQ(feedAt(feedPerMove(planeFilletSlope(), options), 21.0), 1200);
}

// Points a CAM system wrote a tenth of a micrometre apart turn the path by rounding, not by a
// bend: no feed near zero comes of them, and no bend runs below a fifth of F.
TEST(feedRamps, RoundingAndTightBendsDoNotStopTheMachine) {
  PassFeeds pass;
  pass.points = {Vec3(0, 0, 0), Vec3(5, 0, 0), Vec3(5.0001, 0.0001, 0), Vec3(5.0001, 5, 0), Vec3(5.2, 5.2, 0), Vec3(10, 5.2, 0)};
  pass.intervalEnd = {pass.points.size() - 1};
  pass.feeds = {2000};
  pass.sourceLines.assign(pass.points.size(), 3);
  RampOptions options;
  options.programmedFeed = 2000;
  options.normalAccelerationLimit = 10;
  options.rampAcceleration = 100;
  const FeedPerMove m = feedPerMove(pass, options);
  for (const double f : m.feeds) {
    EXPECT_GE(f, 0.2 * 2000 - 1e-9);
    EXPECT_LE(f, 2000) << fmt::format("{:.17g}", f);
  }
  EXPECT_TRUE(feedPerMove(PassFeeds{}, options).points.empty());
  // Without a programmed feed there is no step to cut a ramp at: the interval feeds as they are.
  options.programmedFeed = 0;
  const FeedPerMove plain = feedPerMove(pass, options);
  EXPECT_EQ(plain.points.size(), pass.points.size());
  for (const double f : plain.feeds) EXPECT_NEAR(f, 2000, 1e-9);
}

// Ramps asked for inside a box (where a region's figures are taken) run at their acceleration on
// the moves that reach into it, and faster on the others.
TEST(feedRamps, OutsideTheBoxAskedForRampsRunFaster) {
  RampOptions options;
  options.programmedFeed = 2500;
  options.rampAcceleration = 100;
  options.outsideAcceleration = 1000;
  options.within = std::make_pair(Vec3(21, -1, -1), Vec3(23, 1, 10));  // the fillet's end and the slope's start
  const FeedPerMove m = feedPerMove(planeFilletSlope(), options);
  // Into the fillet from the plane: from 1200 to 2500 mm/min within 0.67 mm at 1000 mm/s^2.
  EXPECT_EQ(feedAt(m, 19.0), 2500);
  EXPECT_GT(feedAt(m, 19.9), 1300);
  EXPECT_LT(feedAt(m, 19.9), 2000);
  EXPECT_EQ(feedAt(m, 21.0), 1200);
  // Out of it onto the slope, whose move reaches into the box: 100 mm/s^2 until done (6.7 mm).
  EXPECT_LT(feedAt(m, 23.0), 1500);
  EXPECT_LT(feedAt(m, 26.0), 2500);
  EXPECT_GT(feedAt(m, 26.0), feedAt(m, 23.0));
  EXPECT_EQ(feedAt(m, 35.0), 2500);
  // A move that crosses the box without an end in it reaches into it: the plane's, here.
  options.within = std::make_pair(Vec3(5, -1, -1), Vec3(6, 1, 10));
  EXPECT_LT(feedAt(feedPerMove(planeFilletSlope(), options), 19.0), 1500);
  // A pass on the box's side is in it, even where the box, taken from samples interpolated
  // between the program's points, ends short of it by the rounding of the last digits.
  options.within = std::make_pair(Vec3(5, -1, -1), Vec3(6, -4e-14, 10));
  EXPECT_LT(feedAt(feedPerMove(planeFilletSlope(), options), 19.0), 1500);
  options.within = std::make_pair(Vec3(5, -1, -1), Vec3(6, -0.001, 10));  // a micrometre short: beside it
  EXPECT_EQ(feedAt(feedPerMove(planeFilletSlope(), options), 19.0), 2500);
  // Without a box, 100 mm/s^2 on both sides.
  options.within.reset();
  EXPECT_LT(feedAt(feedPerMove(planeFilletSlope(), options), 19.0), 1500);
}

// A long move at whose end the ramp reaches it less than a step below its feed runs at its feed:
// the top of the ramp is cut off near its end, not the whole move slowed by a step.
TEST(feedRamps, ALongMoveARampEndsOnKeepsItsFeed) {
  PassFeeds pass = planeFilletSlope();
  pass.feeds = {2500, 2490, 2500};
  RampOptions options;
  options.programmedFeed = 2500;
  options.rampAcceleration = 100;
  const FeedPerMove m = feedPerMove(pass, options);
  EXPECT_EQ(feedAt(m, 10.0), 2500);
  EXPECT_EQ(feedAt(m, 19.9), 2500);
  EXPECT_EQ(feedAt(m, 30.0), 2500);
  // Nor does one whose feed lies between two steps of the ramp (25 mm/min on F2500).
  pass.feeds = {2500, 1200, 2380};
  EXPECT_EQ(feedAt(feedPerMove(pass, options), 35.0), 2380);
}

namespace {

// A bend easing out along X: its curvature falls linearly from 0.2/mm to nothing over 4 mm, then
// a straight of 10 mm; written in pieces of `piece` mm, or in chords that each turn `turn` rad.
PassFeeds easingOut(double piece, double turn) {
  PassFeeds pass;
  Vec3 p(0, 0, 0);
  double heading = 0, since = 0, turned = 0;
  pass.points = {p};
  constexpr double kStep = 0.001, kTaper = 4.0, kStraight = 10.0;  // mm
  for (double s = kStep; s <= kTaper + kStraight + 1e-9; s += kStep) {
    const double curvature = 0.2 * std::max(0.0, 1 - s / kTaper);
    heading += curvature * kStep;
    p += kStep * Vec3(std::cos(heading), 0, std::sin(heading));
    since += kStep, turned += curvature * kStep;
    if (since >= piece - 1e-9 || turned >= turn || s > kTaper + kStraight - kStep / 2) {
      pass.points.push_back(p);
      since = turned = 0;
    }
  }
  pass.intervalEnd = {pass.points.size() - 1};
  pass.feeds = {2500};
  pass.sourceLines.assign(pass.points.size(), 4);
  return pass;
}

}  // namespace

// Where a bend eases out in long chords (each turning a hundredth of a radian, as eased paths are
// written), the speed rises from where the bend begins to ease, as it does over short pieces:
// a chord is not held to the speed of its sharper end.
TEST(feedRamps, ABendEasingOutInLongChordsSpeedsUpAsInShortPieces) {
  RampOptions options;
  options.programmedFeed = 2500;
  options.normalAccelerationLimit = 40;  // mm/s^2: sqrt(40 * 5) = 849 mm/min where the bend is sharpest
  options.rampAcceleration = 250;
  const FeedPerMove fine = feedPerMove(easingOut(0.02, 1), options);
  const FeedPerMove chords = feedPerMove(easingOut(100, 0.01), options);
  ASSERT_LT(chords.points.size(), fine.points.size() / 4);
  double longest = 0;
  for (std::size_t k = 0; k + 1 < chords.points.size(); ++k) longest = std::max(longest, (chords.points[k + 1] - chords.points[k]).norm());
  ASSERT_GT(longest, 0.5);  // the chords near the straight
  for (double x = 0.1; x < 13; x += 0.1) {
    EXPECT_GT(feedAt(chords, x), feedAt(fine, x) - 3 * 25.0) << "x " << x;
    EXPECT_LT(feedAt(chords, x), feedAt(fine, x) + 3 * 25.0) << "x " << x;
  }
  EXPECT_EQ(feedAt(chords, 12.0), 2500);
}

// Without ramps a bend's bound holds both moves beside its sharp point: nothing ramps down to it.
TEST(feedRamps, WithoutRampsACornerHoldsTheMovesBesideIt) {
  PassFeeds pass;
  pass.points = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(10.05, 0.02, 0), Vec3(20, 4, 0)};  // a turn of 0.38 rad
  pass.intervalEnd = {pass.points.size() - 1};
  pass.feeds = {2500};
  pass.sourceLines.assign(pass.points.size(), 5);
  RampOptions options;
  options.programmedFeed = 2500;
  options.normalAccelerationLimit = 40;  // mm/s^2
  const FeedPerMove m = feedPerMove(pass, options);
  ASSERT_EQ(m.feeds.size(), 3u);
  EXPECT_LT(m.feeds[0], 2500);
  EXPECT_LT(m.feeds[1], 2500);
}

// Held to caps at none of its points, a pass ramps as it did; held at some, never faster than
// it did nor than the caps, and each piece within the bound of the move it is part of.
TEST(feedRamps, APassHeldToCapsRunsNoFasterThanBeforeNorThanThem) {
  RampOptions options;
  options.programmedFeed = 2500;
  options.normalAccelerationLimit = 40;
  options.rampAcceleration = 250;
  const PassFeeds pass = easingOut(100, 0.01);
  const FeedPerMove ramped = feedPerMove(pass, options);
  const FeedPerMove same = feedPerMoveHeldTo(pass, ramped, std::vector<double>(ramped.points.size(), INFINITY), options);
  ASSERT_EQ(same.passPointAt.size(), pass.points.size());
  for (double x = 0.05; x < 12.9; x += 0.05) EXPECT_EQ(feedAt(same, x), feedAt(ramped, x)) << "x " << x;
  // Held to 1200 mm/min from x 2 to 3 mm.
  std::vector<double> caps(ramped.points.size(), INFINITY);
  for (std::size_t i = 0; i < caps.size(); ++i)
    if (ramped.points[i].x() > 2 && ramped.points[i].x() < 3) caps[i] = 1200;
  const FeedPerMove held = feedPerMoveHeldTo(pass, ramped, caps, options);
  for (double x = 0.05; x < 12.9; x += 0.05) EXPECT_LE(feedAt(held, x), feedAt(ramped, x)) << "x " << x;
  for (double x = 2.1; x < 2.9; x += 0.05) EXPECT_LE(feedAt(held, x), 1200) << "x " << x;
  EXPECT_EQ(feedAt(held, 12.5), 2500);
}
