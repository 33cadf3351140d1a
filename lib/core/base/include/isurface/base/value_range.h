#pragma once
// The range a colour map spans: the values' own extent, or percentiles of them, so that a few
// outliers (a stop, a spike) do not wash out the map. Non-finite values are ignored.
#include <string>
#include <vector>

namespace isurface {

struct ValueRange {
  double lo = 0, hi = 1;
  bool valid() const { return lo <= hi; }
};

// Values that vary by no more than kNarrowRange of their size (a constant speed, rounding noise)
// are one colour: such a range is widened to span kNarrowRange about its middle (0 to +-1).
constexpr double kNarrowRange = 2e-3;
bool isNarrowRange(const ValueRange& r);
ValueRange widenNarrowRange(ValueRange r);

ValueRange fullRange(const std::vector<float>& values);
// lowPercent, highPercent in [0, 100], low < high.
ValueRange percentileRange(const std::vector<float>& values, double lowPercent, double highPercent);

// "A:B" as a fixed range; throws InputError naming the text when malformed or A > B.
ValueRange parseRange(const std::string& text);

}  // namespace isurface
