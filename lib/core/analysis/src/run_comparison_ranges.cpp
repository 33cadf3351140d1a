// Grouping a run comparison's lines into ranges, ranking the ranges, and the quantities a
// comparison reports.
#include <algorithm>
#include <numeric>

#include "run_comparison_figures.h"

namespace isurface {

namespace {

// -1 where B was faster through the line, +1 slower, 0 the same within the tolerance.
int timeSign(const DifferenceFigures& f, double tolerance) {
  return f.timeDifference > tolerance ? 1 : f.timeDifference < -tolerance ? -1 : 0;
}

double severity(const DifferenceFigures& f, ComparisonQuantity q) {
  switch (q) {
    case ComparisonQuantity::Speed: return std::abs(f.maxSpeedDifference);
    case ComparisonQuantity::Position: return f.maxPositionDistance;
    case ComparisonQuantity::Time: return std::abs(f.timeDifference);
  }
  return 0;
}

}  // namespace

void mergeFigures(DifferenceFigures& into, const DifferenceFigures& f) {
  const std::size_t compared = into.comparedSamples + f.comparedSamples;
  if (compared > 0)
    into.meanSpeedDifference = (into.meanSpeedDifference * double(into.comparedSamples) +
                                f.meanSpeedDifference * double(f.comparedSamples)) / double(compared);
  into.comparedSamples = compared;
  into.timeA += f.timeA;
  into.timeB += f.timeB;
  into.timeDifference = into.timeB - into.timeA;
  into.lengthA += f.lengthA;
  into.lengthB += f.lengthB;
  into.samplesA += f.samplesA;
  into.samplesB += f.samplesB;
  keepLarger(into.maxSpeedDifference, f.maxSpeedDifference);
  keepLarger(into.maxPositionDistance, f.maxPositionDistance);
  keepLarger(into.maxPathDistance, f.maxPathDistance);
  if (f.maxFeedbackDistance) {
    double kept = into.maxFeedbackDistance.value_or(0.0);
    keepLarger(kept, *f.maxFeedbackDistance);
    into.maxFeedbackDistance = kept;
  }
}

void groupRanges(RunComparison& out, const RunComparisonOptions& options) {
  const std::size_t maxLines = std::max<std::size_t>(1, options.maxRangeLines);
  int sign = 0;
  for (std::size_t k = 0; k < out.lines.size(); ++k) {
    const LineDifference& line = out.lines[k];
    mergeFigures(out.total, line.figures);
    const int s = timeSign(line.figures, options.timeTolerance);
    const bool startRange = out.ranges.empty() || s != sign ||
                            out.ranges.back().lineCount >= maxLines;
    if (startRange) {
      out.ranges.push_back(RangeDifference{line.line, line.line, 0, {}});
      sign = s;
    }
    RangeDifference& range = out.ranges.back();
    range.lastLine = line.line;
    ++range.lineCount;
    mergeFigures(range.figures, line.figures);
  }
}

std::vector<std::size_t> RunComparison::worstRanges(ComparisonQuantity q, std::size_t count) const {
  std::vector<std::size_t> order(ranges.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return severity(ranges[x].figures, q) > severity(ranges[y].figures, q);
  });
  order.resize(std::min(count, order.size()));
  return order;
}

const std::vector<float>& RunComparison::sampleValues(ComparisonQuantity q) const {
  switch (q) {
    case ComparisonQuantity::Position: return positionDistance;
    case ComparisonQuantity::Time: return timeDifference;
    case ComparisonQuantity::Speed: break;
  }
  return speedDifference;
}

namespace {

struct QuantityNames {
  ComparisonQuantity quantity;
  const char* name;
  const char* label;  // short: the legend is narrow
  const char* unit;
};

constexpr QuantityNames kQuantities[] = {
    {ComparisonQuantity::Speed, "speed", "Speed B - A", "mm/min"},
    {ComparisonQuantity::Position, "position", "Distance B-A", "mm"},
    {ComparisonQuantity::Time, "time", "Time B - A", "s"},
};

const QuantityNames& namesOf(ComparisonQuantity q) {
  for (const QuantityNames& n : kQuantities)
    if (n.quantity == q) return n;
  return kQuantities[0];
}

}  // namespace

const char* comparisonQuantityName(ComparisonQuantity q) { return namesOf(q).name; }
const char* comparisonQuantityLabel(ComparisonQuantity q) { return namesOf(q).label; }
const char* comparisonQuantityUnit(ComparisonQuantity q) { return namesOf(q).unit; }

std::optional<ComparisonQuantity> parseComparisonQuantity(const std::string& name) {
  for (const QuantityNames& n : kQuantities)
    if (name == n.name) return n.quantity;
  return std::nullopt;
}

}  // namespace isurface
