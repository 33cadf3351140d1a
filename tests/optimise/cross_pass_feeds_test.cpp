// Interval feeds planned across passes: neighbours over the same stretch get the same speed,
// and no feed rises above what the pass's own plan allows.
#include <gtest/gtest.h>

#include "isurface/optimise/cross_pass_feeds.h"

using namespace isurface;

namespace {

// Three straight passes along X, 1 mm apart, each with two intervals (x 0..10 and 10..20).
std::vector<PassFeeds> raster(const std::vector<std::array<double, 2>>& feeds) {
  std::vector<PassFeeds> passes;
  for (std::size_t p = 0; p < feeds.size(); ++p) {
    PassFeeds pass;
    for (int x = 0; x <= 20; ++x) pass.points.push_back(Vec3(x, static_cast<double>(p), 0));
    pass.intervalEnd = {10, 20};
    pass.feeds = {feeds[p][0], feeds[p][1]};
    passes.push_back(pass);
  }
  return passes;
}

}  // namespace

TEST(crossPassFeeds, TheEnvelopeGivesNeighboursTheSameSpeed) {
  std::vector<PassFeeds> passes = raster({{3000, 2000}, {3000, 2600}, {2400, 3000}});
  harmonizeFeedsAcrossPasses(passes, CrossPassRule::Envelope);
  for (const PassFeeds& p : passes) {
    EXPECT_EQ(p.feeds[0], 2000);  // the slowest around, the next interval's cells included
    EXPECT_EQ(p.feeds[1], 2000);
  }
}

TEST(crossPassFeeds, TheMedianLowersTheOddPassOutAndRaisesNone) {
  std::vector<PassFeeds> passes = raster({{2000, 2000}, {3000, 2000}, {2000, 2000}, {2000, 2000}});
  const std::vector<PassFeeds> planned = passes;
  harmonizeFeedsAcrossPasses(passes, CrossPassRule::Median);
  for (std::size_t p = 0; p < passes.size(); ++p)
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_LE(passes[p].feeds[i], planned[p].feeds[i]);
      EXPECT_EQ(passes[p].feeds[i], 2000) << p << " " << i;
    }
}

TEST(crossPassFeeds, EachPassOnItsOwnOrOnePassAloneIsLeftAsPlanned) {
  std::vector<PassFeeds> passes = raster({{3000, 2000}, {2500, 2600}});
  const std::vector<PassFeeds> planned = passes;
  harmonizeFeedsAcrossPasses(passes, CrossPassRule::None);
  for (std::size_t p = 0; p < passes.size(); ++p) EXPECT_EQ(passes[p].feeds, planned[p].feeds);
  std::vector<PassFeeds> one = raster({{3000, 2000}});
  harmonizeFeedsAcrossPasses(one, CrossPassRule::Envelope);
  EXPECT_EQ(one[0].feeds, (std::vector<double>{3000, 2000}));
}

TEST(crossPassFeeds, PassesOnTopOfEachOtherOrWithoutPointsDoNotFail) {
  std::vector<PassFeeds> passes = raster({{3000, 2000}, {2500, 2600}});
  passes[1].points = passes[0].points;  // spacing 0
  harmonizeFeedsAcrossPasses(passes, CrossPassRule::Median);
  EXPECT_EQ(passes[0].feeds, (std::vector<double>{3000, 2000}));
  std::vector<PassFeeds> empty(2);
  harmonizeFeedsAcrossPasses(empty, CrossPassRule::Envelope);
  EXPECT_TRUE(empty[0].feeds.empty());
}
