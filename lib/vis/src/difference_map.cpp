#include "isurface/vis/difference_map.h"

#include <algorithm>
#include <cmath>

namespace isurface::vis {

namespace {

// 1st to 99th percentile, made symmetric about zero for signed differences.
ValueRange differenceRange(const std::vector<float>& values, ComparisonQuantity quantity) {
  const bool isSigned = quantity != ComparisonQuantity::Position;
  const ValueRange p = percentileRange(values, 1, 99);
  double reach = isSigned ? std::max(std::abs(p.lo), std::abs(p.hi)) : std::max(p.hi, 0.0);
  // Identical runs: a small span rather than an empty one, so that the legend still reads.
  if (!(reach > 0)) reach = quantity == ComparisonQuantity::Speed ? 1.0 : 0.001;  // mm/min; s or mm
  return ValueRange{isSigned ? -reach : 0.0, reach};
}

}  // namespace

QualityMapRequest differenceMapRequest(const RunComparison& comparison, ComparisonQuantity quantity,
                                       std::optional<ValueRange> fixedRange, const std::string& colorMap) {
  QualityMapRequest request;
  const bool isSigned = quantity != ComparisonQuantity::Position;
  request.sampleValues = std::make_shared<const std::vector<float>>(comparison.sampleValues(quantity));
  request.valuesLabel = comparisonQuantityLabel(quantity);
  request.valuesUnit = comparisonQuantityUnit(quantity);
  // Iso-lines of a difference zig-zag across the passes wherever it hovers around a level
  // (measurement noise about zero): they hide the pattern instead of showing it.
  request.isoBands = 0;
  request.colorMap = !colorMap.empty() ? colorMap : isSigned ? "coolwarm" : "viridis";
  request.fixedRange = fixedRange ? *fixedRange : differenceRange(*request.sampleValues, quantity);
  return request;
}

QualityMapRequest regionDifferenceMapRequest(const RunComparison& comparison, const Trajectory& before,
                                             LineRange region) {
  const std::vector<float>& all = comparison.sampleValues(ComparisonQuantity::Speed);
  std::vector<float> inRegion;
  before.line.forEachRun(0, all.size(), [&](std::uint32_t line, std::size_t begin, std::size_t end) {
    if (line >= region.first && line <= region.last) inRegion.insert(inRegion.end(), all.begin() + begin, all.begin() + end);
  });
  QualityMapRequest request =
      differenceMapRequest(comparison, ComparisonQuantity::Speed, differenceRange(inRegion, ComparisonQuantity::Speed));
  request.valuesLabel = "Speed after-before";  // one word a line in the legend: this keeps the sign readable
  return request;
}

}  // namespace isurface::vis
