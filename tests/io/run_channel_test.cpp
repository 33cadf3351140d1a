// The per-sample channels kept as runs (line, move index, feed) read back every sample's value.
#include "isurface/base/run_channel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace isurface {
namespace {

std::vector<std::uint32_t> runsOfLines(std::size_t samples, std::mt19937& random) {
  std::vector<std::uint32_t> values;
  std::uniform_int_distribution<int> length(1, 9), line(0, 4);
  while (values.size() < samples) values.insert(values.end(), length(random), std::uint32_t(line(random)));
  values.resize(samples);
  return values;
}

TEST(RunChannel, EverySampleReadsBackInAnyOrder) {
  std::mt19937 random(7);
  const std::vector<std::uint32_t> values = runsOfLines(5000, random);
  const RunChannel<std::uint32_t> channel(values);
  ASSERT_EQ(channel.size(), values.size());
  EXPECT_EQ(channel.toVector(), values);
  for (std::size_t i = 0; i < values.size(); ++i) ASSERT_EQ(channel[i], values[i]) << i;
  // Neighbouring equal values share a run: fewer runs than samples, and no two runs alike side by side.
  EXPECT_LT(channel.runCount(), values.size() / 2);
  for (std::size_t r = 1; r < channel.runCount(); ++r) ASSERT_NE(channel.runValue(r), channel.runValue(r - 1));
  RunChannel<std::uint32_t>::Cursor forward = channel.cursor(), jumping = channel.cursor();
  for (std::size_t i = 0; i < values.size(); ++i) ASSERT_EQ(forward[i], values[i]) << i;
  std::uniform_int_distribution<std::size_t> anywhere(0, values.size() - 1);
  for (int k = 0; k < 5000; ++k) {
    const std::size_t i = anywhere(random);
    ASSERT_EQ(jumping[i], values[i]) << i;
  }
  for (std::size_t i = values.size(); i-- > 0;) ASSERT_EQ(forward[i], values[i]) << i;
}

TEST(RunChannel, RunsVisitedInARangeCoverItExactly) {
  std::mt19937 random(11);
  const std::vector<std::uint32_t> values = runsOfLines(300, random);
  const RunChannel<std::uint32_t> channel(values);
  for (std::size_t begin = 0; begin <= values.size(); begin += 7) {
    for (std::size_t end = begin; end <= values.size() + 3; end += 5) {
      std::vector<std::uint32_t> seen;
      std::size_t expectBegin = begin;
      channel.forEachRun(begin, end, [&](std::uint32_t value, std::size_t from, std::size_t to) {
        ASSERT_EQ(from, expectBegin);
        ASSERT_LT(from, to);
        seen.insert(seen.end(), to - from, value);
        expectBegin = to;
      });
      const std::size_t last = std::min(end, values.size());
      const std::vector<std::uint32_t> expected(values.begin() + std::ptrdiff_t(begin),
                                                values.begin() + std::ptrdiff_t(std::max(begin, last)));
      ASSERT_EQ(seen, expected) << begin << ".." << end;
    }
  }
}

TEST(RunChannel, ResizeAppendAndAssignKeepTheValues) {
  RunChannel<std::uint32_t> channel{5, 5, 6, 6, 6, 7};
  channel.resize(4);
  EXPECT_EQ(channel.toVector(), (std::vector<std::uint32_t>{5, 5, 6, 6}));
  channel.append(6, 2);
  channel.append(9, 0);
  channel.push_back(1);
  EXPECT_EQ(channel.toVector(), (std::vector<std::uint32_t>{5, 5, 6, 6, 6, 6, 1}));
  EXPECT_EQ(channel.runCount(), 3u);
  channel.resize(9, 2);
  EXPECT_EQ(channel.toVector(), (std::vector<std::uint32_t>{5, 5, 6, 6, 6, 6, 1, 2, 2}));
  channel.resize(2);
  EXPECT_EQ(channel.runCount(), 1u);
  channel.resize(0);
  EXPECT_TRUE(channel.empty());
  EXPECT_EQ(channel.runCount(), 0u);
  channel.assign(3, 4);
  EXPECT_EQ(channel, (RunChannel<std::uint32_t>{4, 4, 4}));
  EXPECT_NE(channel, (RunChannel<std::uint32_t>{4, 4}));
}

TEST(RunChannel, FeedsKeepTheirBitsNotANumberIncluded) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const RunChannel<float> feed{600.0f, 600.0f, nan, nan, -0.0f, 0.0f, 1200.5f};
  // NaNs side by side are one run; -0 and +0 stay what they were.
  EXPECT_EQ(feed.runCount(), 5u);
  EXPECT_EQ(feed[1], 600.0f);
  EXPECT_TRUE(std::isnan(feed[2]) && std::isnan(feed[3]));
  EXPECT_TRUE(std::signbit(feed[4]));
  EXPECT_FALSE(std::signbit(feed[5]));
  EXPECT_EQ(feed[6], 1200.5f);
}

TEST(RunChannel, AValueNewEverySampleIsKeptAsAPlainArray) {
  // A trace's measured feed: as runs it would cost 12 bytes a sample, three times the array.
  RunChannel<float> feed;
  std::vector<float> values;
  for (int i = 0; i < 20000; ++i) values.push_back(600.0f + float(i % 97) * 0.5f + (i % 5 == 0 ? 0.0f : 0.25f));
  for (std::size_t i = 0; i < values.size(); ++i) feed.push_back(values[i]);
  EXPECT_TRUE(feed.dense());
  EXPECT_LE(feed.bytes(), values.size() * sizeof(float) * 2);
  EXPECT_EQ(feed.toVector(), values);
  RunChannel<float>::Cursor at = feed.cursor();
  for (std::size_t i = 0; i < values.size(); i += 7) ASSERT_EQ(at[i], values[i]) << i;
  for (std::size_t i = 0; i < values.size(); i += 13) ASSERT_EQ(feed[i], values[i]) << i;
  std::size_t covered = 0;
  feed.forEachRun(100, 200, [&](float v, std::size_t from, std::size_t to) {
    ASSERT_EQ(from, 100 + covered);
    ASSERT_EQ(v, values[from]);
    covered += to - from;
  });
  EXPECT_EQ(covered, 100u);
  feed.resize(10);
  feed.append(5.0f, 3);
  std::vector<float> expected(values.begin(), values.begin() + 10);
  expected.insert(expected.end(), 3, 5.0f);
  EXPECT_EQ(feed.toVector(), expected);
  // A programmed feed, new once a move, stays runs.
  RunChannel<float> programmed;
  for (int i = 0; i < 400000; ++i) programmed.push_back(float(600 + (i / 50) % 40));
  EXPECT_FALSE(programmed.dense());
  EXPECT_LT(programmed.bytes(), 400000u);  // a plain array: 1.6 MB
}

TEST(RunChannel, AnEmptyChannelReadsNothingAndDoesNotCrash) {
  const RunChannel<std::uint32_t> empty;
  EXPECT_EQ(empty[0], 0u);
  RunChannel<std::uint32_t>::Cursor at = empty.cursor();
  EXPECT_EQ(at[5], 0u);
  int runs = 0;
  empty.forEachRun([&](std::uint32_t, std::size_t, std::size_t) { ++runs; });
  EXPECT_EQ(runs, 0);
}

}  // namespace
}  // namespace isurface
