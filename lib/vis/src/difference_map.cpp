#include "isurface/vis/difference_map.h"

#include <algorithm>
#include <cmath>

namespace isurface::vis {

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
  if (fixedRange) {
    request.fixedRange = fixedRange;
  } else {
    const ValueRange p = percentileRange(*request.sampleValues, 1, 99);
    double reach = isSigned ? std::max(std::abs(p.lo), std::abs(p.hi)) : std::max(p.hi, 0.0);
    // Identical runs: a small span rather than an empty one, so that the legend still reads.
    if (!(reach > 0)) reach = quantity == ComparisonQuantity::Speed ? 1.0 : 0.001;  // mm/min; s or mm
    request.fixedRange = ValueRange{isSigned ? -reach : 0.0, reach};
  }
  return request;
}

}  // namespace isurface::vis
