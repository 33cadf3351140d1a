// Min/max pyramid: a column's range splits into at most two partial blocks per level, so every
// column costs O(log n) whatever the number of samples it covers.
#include "isurface/app_model/signal_pyramid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace isurface::app_model {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// NaN stands for "no finite sample": it never wins a comparison.
float minOf(float a, float b) { return std::isnan(a) ? b : (std::isnan(b) ? a : std::min(a, b)); }
float maxOf(float a, float b) { return std::isnan(a) ? b : (std::isnan(b) ? a : std::max(a, b)); }
float finiteOrNaN(float v) { return std::isfinite(v) ? v : kNaN; }

// first + column * count / columns without overflowing for any realistic count: the product is
// split into its whole part and a remainder below columns^2.
std::uint64_t columnStart(std::uint64_t first, std::uint64_t count, std::uint64_t columns, std::uint64_t column) {
  const std::uint64_t whole = count / columns, rest = count % columns;
  return first + column * whole + column * rest / columns;
}

}  // namespace

SignalPyramid::SignalPyramid(std::vector<float> values) {
  low_.push_back(std::move(values));
  high_.emplace_back();
  // Level 1 from the raw values (skipping non-finite ones), then pairs of pairs. A trailing odd
  // element has no parent: queries reach it through the finer level, so nothing is lost.
  for (std::size_t level = 1; low_[level - 1].size() >= 2; ++level) {
    const std::vector<float>& finerLow = low_[level - 1];
    const std::vector<float>& finerHigh = level == 1 ? low_[0] : high_[level - 1];
    const std::size_t n = finerLow.size() / 2;
    std::vector<float> low(n), high(n);
    for (std::size_t j = 0; j < n; ++j) {
      float a = finerLow[2 * j], b = finerLow[2 * j + 1];
      float c = finerHigh[2 * j], d = finerHigh[2 * j + 1];
      if (level == 1) {
        a = c = finiteOrNaN(a);
        b = d = finiteOrNaN(b);
      }
      low[j] = minOf(a, b);
      high[j] = maxOf(c, d);
    }
    // References into low_/high_ die with the push_back: they are not used after it.
    low_.push_back(std::move(low));
    high_.push_back(std::move(high));
  }
}

std::size_t SignalPyramid::size() const { return low_.empty() ? 0 : low_[0].size(); }

float SignalPyramid::value(std::size_t i) const { return i < size() ? low_[0][i] : kNaN; }

void SignalPyramid::accumulate(std::size_t first, std::size_t last, float& low, float& high) const {
  // Bottom-up: at each level take the odd block at either end, then halve. The ranges stay
  // within the level's whole blocks, which exist because levels round their size down.
  std::size_t a = first, b = last;
  for (std::size_t level = 0; a < b; ++level, a >>= 1, b >>= 1) {
    if (level == 0) {
      const std::vector<float>& values = low_[0];
      if (a & 1) {
        const float v = finiteOrNaN(values[a++]);
        low = minOf(low, v);
        high = maxOf(high, v);
      }
      if (b & 1) {
        const float v = finiteOrNaN(values[--b]);
        low = minOf(low, v);
        high = maxOf(high, v);
      }
    } else {
      if (a & 1) {
        low = minOf(low, low_[level][a]);
        high = maxOf(high, high_[level][a]);
        ++a;
      }
      if (b & 1) {
        --b;
        low = minOf(low, low_[level][b]);
        high = maxOf(high, high_[level][b]);
      }
    }
  }
}

Envelope SignalPyramid::envelope(std::size_t first, std::size_t last, int columns) const {
  Envelope result;
  if (columns <= 0) return result;
  result.low.assign(static_cast<std::size_t>(columns), kNaN);
  result.high.assign(static_cast<std::size_t>(columns), kNaN);
  last = std::min(last, size());
  if (first >= last) return result;
  const std::uint64_t count = last - first, columnCount = static_cast<std::uint64_t>(columns);
  std::uint64_t begin = first;
  for (std::uint64_t c = 0; c < columnCount; ++c) {
    const std::uint64_t end = columnStart(first, count, columnCount, c + 1);
    float low = kNaN, high = kNaN;
    accumulate(static_cast<std::size_t>(begin), static_cast<std::size_t>(end), low, high);
    result.low[c] = low;
    result.high[c] = high;
    begin = end;
  }
  return result;
}

std::pair<float, float> SignalPyramid::range(std::size_t first, std::size_t last) const {
  float low = kNaN, high = kNaN;
  last = std::min(last, size());
  if (first < last) accumulate(first, last, low, high);
  return {low, high};
}

std::size_t sampleAtColumn(std::size_t first, std::size_t last, int columns, double column) {
  if (columns <= 0 || last <= first || !(column > 0)) return first;  // NaN goes to the start too
  if (column >= columns) return last - 1;
  // The sample must lie in the range envelope() draws in that pixel column (so the cursor and
  // the curve agree); the fraction picks proportionally within it.
  const std::uint64_t count = last - first, columnCount = static_cast<std::uint64_t>(columns);
  const double whole = std::floor(column);
  const auto c = static_cast<std::uint64_t>(whole);
  const std::uint64_t begin = columnStart(first, count, columnCount, c);
  const std::uint64_t end = columnStart(first, count, columnCount, c + 1);
  if (end <= begin) return static_cast<std::size_t>(std::min<std::uint64_t>(begin, last - 1));
  const auto offset = static_cast<std::uint64_t>((column - whole) * static_cast<double>(end - begin));
  return static_cast<std::size_t>(begin + std::min(offset, end - begin - 1));
}

}  // namespace isurface::app_model
