// Per-column min/max of the signal curves, checked against a plain scan of the samples.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "isurface/app_model/signal_pyramid.h"

using namespace isurface::app_model;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

std::pair<float, float> bruteRange(const std::vector<float>& values, std::size_t first, std::size_t last) {
  float low = kNaN, high = kNaN;
  for (std::size_t i = first; i < last && i < values.size(); ++i) {
    if (!std::isfinite(values[i])) continue;
    if (std::isnan(low) || values[i] < low) low = values[i];
    if (std::isnan(high) || values[i] > high) high = values[i];
  }
  return {low, high};
}

// Column c covers [first + c*n/columns, first + (c+1)*n/columns), n = last - first.
std::pair<std::size_t, std::size_t> bruteColumn(std::size_t first, std::size_t last, int columns, int c) {
  const std::uint64_t n = last - first;
  return {first + c * n / columns, first + (c + 1) * n / columns};
}

// Equal as floats, or both NaN.
::testing::AssertionResult sameValue(float a, float b) {
  if ((std::isnan(a) && std::isnan(b)) || a == b) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " != " << b;
}

void expectEnvelopeMatches(const SignalPyramid& pyramid, const std::vector<float>& values, std::size_t first,
                           std::size_t last, int columns) {
  const Envelope e = pyramid.envelope(first, last, columns);
  ASSERT_EQ(e.low.size(), static_cast<std::size_t>(columns));
  ASSERT_EQ(e.high.size(), static_cast<std::size_t>(columns));
  for (int c = 0; c < columns; ++c) {
    const auto [begin, end] = bruteColumn(first, last, columns, c);
    const auto [low, high] = bruteRange(values, begin, end);
    ASSERT_TRUE(sameValue(e.low[c], low)) << "n=" << values.size() << " [" << first << "," << last << ") columns="
                                          << columns << " column " << c;
    ASSERT_TRUE(sameValue(e.high[c], high)) << "n=" << values.size() << " [" << first << "," << last
                                            << ") columns=" << columns << " column " << c;
  }
}

std::vector<float> randomValues(std::size_t n, std::mt19937& random, double nonFiniteShare = 0) {
  std::normal_distribution<float> normal(0, 10);
  std::uniform_real_distribution<double> share(0, 1);
  std::vector<float> values(n);
  for (auto& v : values) {
    v = normal(random);
    if (share(random) < nonFiniteShare) v = share(random) < 0.5 ? kNaN : (share(random) < 0.5 ? kInf : -kInf);
  }
  return values;
}

}  // namespace

TEST(signalPyramid, EmptyPyramid) {
  const SignalPyramid empty;
  EXPECT_EQ(empty.size(), 0u);
  EXPECT_TRUE(std::isnan(empty.value(0)));
  const auto [low, high] = empty.range(0, 10);
  EXPECT_TRUE(std::isnan(low) && std::isnan(high));
  const Envelope e = empty.envelope(0, 10, 4);
  ASSERT_EQ(e.low.size(), 4u);
  for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isnan(e.low[c]) && std::isnan(e.high[c]));
  EXPECT_TRUE(SignalPyramid(std::vector<float>{}).envelope(0, 0, 0).low.empty());
}

TEST(signalPyramid, KeepsTheValues) {
  const std::vector<float> values = {1.5f, -2, kNaN, 7};
  const SignalPyramid pyramid(values);
  ASSERT_EQ(pyramid.size(), 4u);
  EXPECT_EQ(pyramid.value(0), 1.5f);
  EXPECT_EQ(pyramid.value(1), -2.0f);
  EXPECT_TRUE(std::isnan(pyramid.value(2)));
  EXPECT_EQ(pyramid.value(3), 7.0f);
  EXPECT_TRUE(std::isnan(pyramid.value(4)));
}

TEST(signalPyramid, EnvelopesMatchBruteForceOnRandomData) {
  std::mt19937 random(42);
  for (const std::size_t n : {1u, 2u, 3u, 5u, 8u, 17u, 64u, 100u, 1023u, 1024u, 1025u, 5000u, 65537u}) {
    const std::vector<float> values = randomValues(n, random);
    const SignalPyramid pyramid(values);
    std::uniform_int_distribution<std::size_t> position(0, n);
    for (int trial = 0; trial < 40; ++trial) {
      std::size_t first = position(random), last = position(random);
      if (first > last) std::swap(first, last);
      const std::size_t count = last - first;
      // Fewer, as many and more columns than samples.
      const int maxColumns = static_cast<int>(std::min<std::size_t>(2 * count + 3, 3000));
      const int columns = std::uniform_int_distribution<int>(1, maxColumns)(random);
      expectEnvelopeMatches(pyramid, values, first, last, columns);
      if (HasFatalFailure()) return;
    }
    expectEnvelopeMatches(pyramid, values, 0, n, 1);
    expectEnvelopeMatches(pyramid, values, 0, n, 1920);
  }
}

TEST(signalPyramid, RangesMatchBruteForce) {
  std::mt19937 random(3);
  const std::vector<float> values = randomValues(10000, random, 0.05);
  const SignalPyramid pyramid(values);
  std::uniform_int_distribution<std::size_t> position(0, values.size());
  for (int trial = 0; trial < 2000; ++trial) {
    std::size_t first = position(random), last = position(random);
    if (first > last) std::swap(first, last);
    const auto [low, high] = pyramid.range(first, last);
    const auto [bruteLow, bruteHigh] = bruteRange(values, first, last);
    ASSERT_TRUE(sameValue(low, bruteLow)) << first << ".." << last;
    ASSERT_TRUE(sameValue(high, bruteHigh)) << first << ".." << last;
  }
  // Past the end is clipped; an inverted range is empty.
  EXPECT_TRUE(sameValue(pyramid.range(9990, 20000).first, bruteRange(values, 9990, 10000).first));
  EXPECT_TRUE(std::isnan(pyramid.range(20, 10).first));
}

TEST(signalPyramid, NonFiniteSamplesAreSkipped) {
  std::mt19937 random(11);
  const std::vector<float> values = randomValues(3000, random, 0.3);
  const SignalPyramid pyramid(values);
  for (const int columns : {1, 7, 100, 2999, 3000, 3001, 7000}) expectEnvelopeMatches(pyramid, values, 0, 3000, columns);
  expectEnvelopeMatches(pyramid, values, 17, 2503, 333);

  const SignalPyramid mixed({kNaN, 3, kInf, -1, -kInf, kNaN});
  const auto [low, high] = mixed.range(0, 6);
  EXPECT_EQ(low, -1.0f);
  EXPECT_EQ(high, 3.0f);
}

TEST(signalPyramid, ColumnsWithoutFiniteSamplesAreNaN) {
  std::vector<float> values(1000, kNaN);
  for (std::size_t i = 500; i < 600; ++i) values[i] = static_cast<float>(i);
  const SignalPyramid pyramid(values);
  const Envelope e = pyramid.envelope(0, 1000, 10);
  for (int c = 0; c < 10; ++c) {
    if (c == 5) {
      EXPECT_EQ(e.low[c], 500.0f);
      EXPECT_EQ(e.high[c], 599.0f);
    } else {
      EXPECT_TRUE(std::isnan(e.low[c]) && std::isnan(e.high[c])) << "column " << c;
    }
  }
  const auto [low, high] = SignalPyramid(std::vector<float>(77, kInf)).range(0, 77);
  EXPECT_TRUE(std::isnan(low) && std::isnan(high));
}

TEST(signalPyramid, MoreColumnsThanSamplesShowEachSampleOnce) {
  const std::vector<float> values = {4, 1, 9, 2, 6};
  const SignalPyramid pyramid(values);
  const Envelope e = pyramid.envelope(0, 5, 12);
  std::vector<float> shown;
  for (int c = 0; c < 12; ++c) {
    if (std::isnan(e.low[c])) continue;
    EXPECT_EQ(e.low[c], e.high[c]);
    shown.push_back(e.low[c]);
  }
  EXPECT_EQ(shown, values);
}

TEST(signalPyramid, LargeSignalCoarseColumns) {
  std::mt19937 random(5);
  const std::vector<float> values = randomValues(1 << 20 | 12345, random, 0.001);
  const SignalPyramid pyramid(values);
  expectEnvelopeMatches(pyramid, values, 0, values.size(), 1000);
  expectEnvelopeMatches(pyramid, values, 123457, 987651, 777);
  expectEnvelopeMatches(pyramid, values, 500000, 500100, 1920);
}

TEST(signalPyramid, SampleAtColumnIsTheColumnsFirstSample) {
  std::mt19937 random(9);
  std::uniform_int_distribution<std::size_t> position(0, 100000);
  for (int trial = 0; trial < 200; ++trial) {
    std::size_t first = position(random), last = position(random);
    if (first > last) std::swap(first, last);
    if (first == last) continue;
    const int columns = std::uniform_int_distribution<int>(1, 4000)(random);
    std::size_t previous = first;
    for (int c = 0; c < columns; c += 1 + columns / 50) {
      const auto [begin, end] = bruteColumn(first, last, columns, c);
      const std::size_t atStart = sampleAtColumn(first, last, columns, c);
      EXPECT_EQ(atStart, std::min(begin, last - 1)) << "column " << c;
      // Within a column, fractional positions stay inside the range its envelope covers.
      for (const double fraction : {0.001, 0.5, 0.999}) {
        const std::size_t inside = sampleAtColumn(first, last, columns, c + fraction);
        EXPECT_GE(inside, atStart);
        EXPECT_LE(inside, end == begin ? begin : end - 1) << "column " << c + fraction;
      }
      EXPECT_GE(atStart, previous);
      previous = atStart;
    }
  }
}

TEST(signalPyramid, SampleAtColumnClamps) {
  EXPECT_EQ(sampleAtColumn(100, 200, 50, -3), 100u);
  EXPECT_EQ(sampleAtColumn(100, 200, 50, 0), 100u);
  EXPECT_EQ(sampleAtColumn(100, 200, 50, 49.99), 199u);
  EXPECT_EQ(sampleAtColumn(100, 200, 50, 50), 199u);
  EXPECT_EQ(sampleAtColumn(100, 200, 50, 1e9), 199u);
  EXPECT_EQ(sampleAtColumn(100, 200, 50, std::nan("")), 100u);
  EXPECT_EQ(sampleAtColumn(100, 100, 50, 10), 100u);
  EXPECT_EQ(sampleAtColumn(100, 200, 0, 10), 100u);
  // Ten samples over a hundred columns: ten columns per sample.
  EXPECT_EQ(sampleAtColumn(0, 10, 100, 9.9), 0u);
  EXPECT_EQ(sampleAtColumn(0, 10, 100, 10), 1u);
  EXPECT_EQ(sampleAtColumn(0, 10, 100, 95), 9u);
  // A hundred samples over ten columns: the first of each block of ten.
  EXPECT_EQ(sampleAtColumn(0, 100, 10, 3), 30u);
  EXPECT_EQ(sampleAtColumn(0, 100, 10, 3.5), 35u);
}

// A long run's curve reads what a view shows from its source, not the run: a whole-run view of
// 1,000 columns over 10 M samples reads at most the ends of each column (under two blocks).
TEST(signalPyramid, ViewsReadOnlyWhatTheyShowFromTheSource) {
  const std::size_t n = 10'000'000;
  const auto valueAt = [](std::size_t i) { return static_cast<float>(std::sin(0.001 * double(i)) * 100 + (i % 977 == 0 ? 500 : 0)); };
  std::size_t read = 0;
  const SignalPyramid pyramid(n, [&](std::size_t first, std::size_t last, float* out) {
    read += last - first;
    for (std::size_t i = first; i < last; ++i) out[i - first] = valueAt(i);
  });
  EXPECT_EQ(read, n - n % 64);  // built in one pass
  read = 0;
  const Envelope whole = pyramid.envelope(0, n, 1000);
  EXPECT_LE(read, 1000u * 128);
  for (int c : {0, 1, 417, 999}) {
    const auto [begin, end] = bruteColumn(0, n, 1000, c);
    float low = valueAt(begin), high = low;
    for (std::size_t i = begin; i < end; ++i) low = std::min(low, valueAt(i)), high = std::max(high, valueAt(i));
    EXPECT_EQ(whole.low[c], low) << c;
    EXPECT_EQ(whole.high[c], high) << c;
  }
  read = 0;
  EXPECT_EQ(pyramid.envelope(0, n, 1000).low, whole.low);  // the same view again: nothing read
  EXPECT_EQ(read, 0u);
  const Envelope zoomed = pyramid.envelope(5'000'000, 5'003'000, 1000);
  EXPECT_EQ(read, 3000u);
  for (int c = 0; c < 1000; ++c) {
    const auto [begin, end] = bruteColumn(5'000'000, 5'003'000, 1000, c);
    float low = valueAt(begin), high = low;
    for (std::size_t i = begin; i < end; ++i) low = std::min(low, valueAt(i)), high = std::max(high, valueAt(i));
    ASSERT_EQ(zoomed.low[c], low) << c;
    ASSERT_EQ(zoomed.high[c], high) << c;
  }
  EXPECT_EQ(pyramid.value(1234567), valueAt(1234567));
  EXPECT_EQ(pyramid.values(n - 2, n + 5), (std::vector<float>{valueAt(n - 2), valueAt(n - 1)}));
  EXPECT_TRUE(std::isnan(pyramid.value(n)));
}
