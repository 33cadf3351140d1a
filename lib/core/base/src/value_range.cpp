#include "isurface/base/value_range.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "isurface/base/diagnostic.h"

namespace isurface {

namespace {
// Percentiles of more values than this are estimated from an even subsample: a quality map's
// range does not need more precision than a 1-in-1,000,000 rank.
constexpr std::size_t kMaxRankedValues = 1u << 20;

}  // namespace

bool isNarrowRange(const ValueRange& r) {
  const double size = std::max(std::abs(r.lo), std::abs(r.hi));
  return r.valid() && std::isfinite(size) && r.hi - r.lo <= kNarrowRange * size * (1 + 1e-9);
}

ValueRange widenNarrowRange(ValueRange r) {
  if (!isNarrowRange(r)) return r;
  const double middle = 0.5 * (r.lo + r.hi);
  const double half = middle == 0 && r.lo == r.hi ? 1.0 : 0.5 * kNarrowRange * std::max(std::abs(r.lo), std::abs(r.hi));
  return {middle - half, middle + half};
}

ValueRange fullRange(const std::vector<float>& values) {
  double lo = INFINITY, hi = -INFINITY;
  for (float v : values)
    if (std::isfinite(v)) lo = std::min<double>(lo, v), hi = std::max<double>(hi, v);
  if (!(lo <= hi)) return {0, 1};
  return widenNarrowRange({lo, hi});
}

ValueRange percentileRange(const std::vector<float>& values, double lowPercent, double highPercent) {
  std::vector<float> finite;
  const std::size_t step = std::max<std::size_t>(1, values.size() / kMaxRankedValues);
  finite.reserve(values.size() / step + 1);
  for (std::size_t i = 0; i < values.size(); i += step)
    if (std::isfinite(values[i])) finite.push_back(values[i]);
  if (finite.empty()) return {0, 1};
  auto rank = [&](double percent) {
    const std::size_t k = static_cast<std::size_t>(std::llround(percent / 100.0 * (finite.size() - 1)));
    std::nth_element(finite.begin(), finite.begin() + k, finite.end());
    return static_cast<double>(finite[k]);
  };
  const double lo = rank(lowPercent), hi = rank(highPercent);
  return widenNarrowRange({lo, hi});
}

ValueRange parseRange(const std::string& text) {
  const auto colon = text.find(':');
  auto fail = [&]() -> ValueRange {
    throw InputError(Diagnostic{"", 0, 0, "bad range '" + text + "': expected A:B with numbers A <= B"});
  };
  if (colon == std::string::npos) return fail();
  const std::string a = text.substr(0, colon), b = text.substr(colon + 1);
  char* end = nullptr;
  const double lo = std::strtod(a.c_str(), &end);
  if (a.empty() || *end != '\0') return fail();
  const double hi = std::strtod(b.c_str(), &end);
  if (b.empty() || *end != '\0' || !std::isfinite(lo) || !std::isfinite(hi) || lo > hi) return fail();
  // A range the user gives is kept as given; only a single value needs room for colours.
  return lo == hi ? widenNarrowRange({lo, hi}) : ValueRange{lo, hi};
}

}  // namespace isurface
