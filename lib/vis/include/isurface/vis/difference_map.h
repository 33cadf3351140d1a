#pragma once
// The map of a run comparison: run A's surface coloured by how run B differs from it at the
// same place, with a diverging colour map centred on zero for signed differences.
#include <memory>
#include <optional>
#include <string>

#include "isurface/core/run_comparison.h"
#include "isurface/vis/quality_map.h"

namespace isurface::vis {

// Speed and time differences are signed: the range is symmetric about zero (the larger of the
// 1st and 99th percentile magnitudes) on the diverging "coolwarm" map, so that white is "the
// same" and blue/red tell which run was faster. Position distances are magnitudes: 0 to the
// 99th percentile on "viridis". A fixed range or another colour map may be given instead.
QualityMapRequest differenceMapRequest(const RunComparison& comparison, ComparisonQuantity quantity,
                                       std::optional<ValueRange> fixedRange = std::nullopt,
                                       const std::string& colorMap = "");

}  // namespace isurface::vis
