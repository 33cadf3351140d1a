// Ramped feeds made to agree from one pass to the next: no point of a pass runs faster than the
// pass beside it by more than the step, whichever way the passes run, and passes too far apart
// do not hold each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "isurface/optimise/speeds_across_passes.h"

using namespace isurface;

namespace {

// A straight pass along X at `y` from x 0 to 20 mm in moves of 0.5 mm, at F2500 except
// `slow` mm/min over x 10-12 (0: nowhere); run towards -X when `backwards`.
FeedPerMove straightPass(double y, double slow, bool backwards = false) {
  FeedPerMove pass;
  for (int k = 0; k <= 40; ++k) pass.points.emplace_back(0.5 * k, y, 0.0);
  for (int k = 0; k < 40; ++k) {
    const double middle = 0.5 * k + 0.25;
    pass.feeds.push_back(slow > 0 && middle > 10 && middle < 12 ? slow : 2500);
  }
  if (backwards) {
    std::reverse(pass.points.begin(), pass.points.end());
    std::reverse(pass.feeds.begin(), pass.feeds.end());
  }
  return pass;
}

// Every pass programmed at F2500: a step of 2 % is 50 mm/min.
std::vector<double> feedsOf(const std::vector<FeedPerMove>& passes) { return std::vector<double>(passes.size(), 2500.0); }

// The cap (mm/min) at the point of `pass` nearest x.
double capAt(const FeedPerMove& pass, const std::vector<double>& caps, double x) {
  std::size_t best = 0;
  for (std::size_t i = 0; i < pass.points.size(); ++i)
    if (std::fabs(pass.points[i].x() - x) < std::fabs(pass.points[best].x() - x)) best = i;
  return caps[best];
}

}  // namespace

TEST(speedsAcrossPasses, APassSlowerThanItsNeighboursHoldsThemToItsSpeedPlusAStepEach) {
  for (const bool zigzag : {false, true}) {
    const std::vector<FeedPerMove> passes = {straightPass(0.0, 2500), straightPass(0.5, 1000, zigzag), straightPass(1.0, 0),
                                             straightPass(1.5, 0, zigzag)};
    const auto caps = speedCapsAcrossPasses(passes, feedsOf(passes), {0.02, 2.0});
    ASSERT_EQ(caps.size(), 4u);
    // The slow pass keeps its speed; the others are held to it, a step per pass between.
    EXPECT_EQ(capAt(passes[1], caps[1], 11.0), 1000);
    EXPECT_EQ(capAt(passes[0], caps[0], 11.0), 1050);
    EXPECT_EQ(capAt(passes[2], caps[2], 11.0), 1050);
    EXPECT_EQ(capAt(passes[3], caps[3], 11.0), 1100);
    // Away from the slow stretch every pass keeps its feed.
    for (std::size_t p = 0; p < passes.size(); ++p) {
      EXPECT_EQ(capAt(passes[p], caps[p], 3.0), 2500) << "pass " << p;
      EXPECT_EQ(capAt(passes[p], caps[p], 18.0), 2500) << "pass " << p;
    }
  }
}

TEST(speedsAcrossPasses, PassesFartherApartThanTheReachOrOfAnotherFeedDoNotHoldEachOther) {
  const std::vector<FeedPerMove> passes = {straightPass(0.0, 1000), straightPass(3.0, 0)};
  const auto caps = speedCapsAcrossPasses(passes, feedsOf(passes), {0.02, 2.0});
  EXPECT_EQ(capAt(passes[1], caps[1], 11.0), INFINITY);
  EXPECT_EQ(capAt(passes[0], caps[0], 11.0), INFINITY);
  // A pass of another feed beside it is other work (a finishing pass beside a roughing one).
  const std::vector<FeedPerMove> beside = {straightPass(0.0, 1000), straightPass(0.5, 0)};
  EXPECT_EQ(capAt(beside[1], speedCapsAcrossPasses(beside, {2500.0, 3000.0}, {0.02, 2.0})[1], 11.0), INFINITY);
}

// A neighbour's long move is found wherever a point lies beside it, not only near its ends.
TEST(speedsAcrossPasses, ALongSlowMoveOfTheNeighbourHoldsThePointsBesideIt) {
  FeedPerMove slow;
  slow.points = {Vec3(0, 0, 0), Vec3(50, 0, 0)};
  slow.feeds = {1000};
  const std::vector<FeedPerMove> passes = {slow, straightPass(0.5, 0)};
  const auto caps = speedCapsAcrossPasses(passes, feedsOf(passes), {0.02, 2.0});
  for (const double x : {3.0, 11.0, 18.0}) EXPECT_EQ(capAt(passes[1], caps[1], x), 1050) << "x " << x;
}

TEST(speedsAcrossPasses, NothingToHoldHoldsNothing) {
  EXPECT_TRUE(speedCapsAcrossPasses({}, {}, {0.02, 2.0}).empty());
  const std::vector<FeedPerMove> one = {straightPass(0.0, 1000)};
  const auto caps = speedCapsAcrossPasses(one, feedsOf(one), {0.02, 2.0});
  ASSERT_EQ(caps.size(), 1u);
  ASSERT_EQ(caps[0].size(), one[0].points.size());
  for (const double cap : caps[0]) EXPECT_EQ(cap, INFINITY);
  // A pass without moves has nothing to cap and holds no other.
  const std::vector<FeedPerMove> empty = {FeedPerMove{}, straightPass(0.5, 0)};
  const auto none = speedCapsAcrossPasses(empty, feedsOf(empty), {0.02, 2.0});
  EXPECT_TRUE(none[0].empty());
  EXPECT_EQ(capAt(empty[1], none[1], 11.0), INFINITY);
}

// A long move across space (a diagonal of a metre) is found beside any of its points.
TEST(speedsAcrossPasses, ALongDiagonalMoveIsFoundAlongItsLength) {
  FeedPerMove diagonal;
  diagonal.points = {Vec3(0, 0, 0), Vec3(600, 600, 600)};
  diagonal.feeds = {1000};
  FeedPerMove beside;
  for (int k = 0; k <= 60; ++k) beside.points.emplace_back(10.0 * k + 0.5, 10.0 * k, 10.0 * k);
  beside.feeds.assign(60, 2500);
  const std::vector<FeedPerMove> passes = {diagonal, beside};
  const auto caps = speedCapsAcrossPasses(passes, feedsOf(passes), {0.02, 2.0});
  for (std::size_t i = 0; i < beside.points.size(); ++i) EXPECT_EQ(caps[1][i], 1050) << "point " << i;
}
