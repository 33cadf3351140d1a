// Min/max pyramid: a column's range splits into at most two partial blocks per level and two
// ends read from the source, so every column costs O(log n) whatever the number of samples it
// covers.
#include "isurface/app_model/signal_pyramid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace isurface::app_model {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr std::size_t kBlock = 64;             // samples in a block of the finest level
constexpr std::size_t kPiece = kBlock * 1024;  // samples read at once while building

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

SignalPyramid::SignalPyramid(std::vector<float> values)
    : SignalPyramid(std::make_shared<const std::vector<float>>(std::move(values))) {}

SignalPyramid::SignalPyramid(std::shared_ptr<const std::vector<float>> held)
    : SignalPyramid(held->size(), [held](std::size_t first, std::size_t last, float* out) {
        std::copy(held->begin() + static_cast<std::ptrdiff_t>(first), held->begin() + static_cast<std::ptrdiff_t>(last), out);
      }) {}

SignalPyramid::SignalPyramid(std::size_t size, Source source) : size_(size), source_(std::move(source)) {
  const std::size_t blocks = size_ / kBlock;
  if (blocks == 0) return;
  std::vector<float> low(blocks), high(blocks), piece(kPiece);
  for (std::size_t first = 0; first < blocks * kBlock; first += kPiece) {
    const std::size_t last = std::min(blocks * kBlock, first + kPiece);
    source_(first, last, piece.data());
    for (std::size_t b = first / kBlock; b < last / kBlock; ++b) {
      float l = kNaN, h = kNaN;
      for (std::size_t i = b * kBlock - first, end = i + kBlock; i < end; ++i) {
        const float v = finiteOrNaN(piece[i]);
        l = minOf(l, v);
        h = maxOf(h, v);
      }
      low[b] = l;
      high[b] = h;
    }
  }
  low_.push_back(std::move(low));
  high_.push_back(std::move(high));
  // Pairs of pairs. A trailing odd block has no parent: queries reach it through the finer
  // level, so nothing is lost.
  for (std::size_t level = 1; low_[level - 1].size() >= 2; ++level) {
    const std::size_t n = low_[level - 1].size() / 2;
    std::vector<float> coarserLow(n), coarserHigh(n);
    for (std::size_t j = 0; j < n; ++j) {
      coarserLow[j] = minOf(low_[level - 1][2 * j], low_[level - 1][2 * j + 1]);
      coarserHigh[j] = maxOf(high_[level - 1][2 * j], high_[level - 1][2 * j + 1]);
    }
    low_.push_back(std::move(coarserLow));
    high_.push_back(std::move(coarserHigh));
  }
}

float SignalPyramid::value(std::size_t i) const {
  if (i >= size_) return kNaN;
  float v = kNaN;
  source_(i, i + 1, &v);
  return v;
}

std::vector<float> SignalPyramid::values(std::size_t first, std::size_t last) const {
  last = std::min(last, size_);
  if (first >= last) return {};
  std::vector<float> out(last - first);
  source_(first, last, out.data());
  return out;
}

void SignalPyramid::accumulateRaw(std::size_t first, std::size_t last, float& low, float& high) const {
  if (first >= last) return;
  float piece[kBlock];
  for (std::size_t from = first; from < last; from += kBlock) {
    const std::size_t to = std::min(last, from + kBlock);
    source_(from, to, piece);
    for (std::size_t i = 0; i < to - from; ++i) {
      const float v = finiteOrNaN(piece[i]);
      low = minOf(low, v);
      high = maxOf(high, v);
    }
  }
}

void SignalPyramid::accumulate(std::size_t first, std::size_t last, float& low, float& high) const {
  // The ends that are not whole blocks from the source; whole blocks bottom-up: at each level
  // take the odd block at either end, then halve. The ranges stay within the level's whole
  // blocks, which exist because levels round their size down.
  const std::size_t a0 = (first + kBlock - 1) / kBlock, b0 = last / kBlock;
  if (a0 >= b0) {
    accumulateRaw(first, last, low, high);
    return;
  }
  accumulateRaw(first, a0 * kBlock, low, high);
  accumulateRaw(b0 * kBlock, last, low, high);
  std::size_t a = a0, b = b0;
  for (std::size_t level = 0; a < b; ++level, a >>= 1, b >>= 1) {
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

Envelope SignalPyramid::envelope(std::size_t first, std::size_t last, int columns) const {
  Remembered& r = *remembered_;
  if (r.first == first && r.last == last && r.columns == columns) return r.envelope;
  Envelope result;
  if (columns > 0) {
    result.low.assign(static_cast<std::size_t>(columns), kNaN);
    result.high.assign(static_cast<std::size_t>(columns), kNaN);
  }
  const std::size_t end = std::min(last, size_);
  if (columns > 0 && first < end) {
    const std::uint64_t count = end - first, columnCount = static_cast<std::uint64_t>(columns);
    // Zoomed in (under two blocks a column): one read of the shown samples.
    std::vector<float> shown;
    if (count < 2 * kBlock * columnCount) shown = values(first, end);
    std::uint64_t begin = first;
    for (std::uint64_t c = 0; c < columnCount; ++c) {
      const std::uint64_t stop = columnStart(first, count, columnCount, c + 1);
      float low = kNaN, high = kNaN;
      if (!shown.empty()) {
        for (std::uint64_t i = begin; i < stop; ++i) {
          const float v = finiteOrNaN(shown[i - first]);
          low = minOf(low, v);
          high = maxOf(high, v);
        }
      } else {
        accumulate(static_cast<std::size_t>(begin), static_cast<std::size_t>(stop), low, high);
      }
      result.low[c] = low;
      result.high[c] = high;
      begin = stop;
    }
  }
  r = Remembered{first, last, columns, result};
  return result;
}

std::pair<float, float> SignalPyramid::range(std::size_t first, std::size_t last) const {
  float low = kNaN, high = kNaN;
  last = std::min(last, size_);
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
