#pragma once
// The map of a run comparison: run A's surface coloured by how run B differs from it at the
// same place, with a diverging colour map centred on zero for signed differences.
#include <memory>
#include <optional>
#include <string>

#include "isurface/fitting/constant_speed_intervals.h"
#include "isurface/analysis/run_comparison.h"
#include "isurface/map/quality_map.h"

namespace isurface::vis {

// Speed and time differences are signed: the range is symmetric about zero (the larger of the
// 1st and 99th percentile magnitudes) on the diverging "coolwarm" map, so that white is "the
// same" and blue/red tell which run was faster. Position distances are magnitudes: 0 to the
// 99th percentile on "viridis". A fixed range or another colour map may be given instead.
QualityMapRequest differenceMapRequest(const RunComparison& comparison, ComparisonQuantity quantity,
                                       std::optional<ValueRange> fixedRange = std::nullopt,
                                       const std::string& colorMap = "");

// The map of a re-optimised region (run A before, B after): the speed difference, after minus
// before (mm/min), on the surface before, its symmetric range taken from the samples of the
// region's lines only: elsewhere the runs hardly differ, and a range over the whole surface
// would shrink towards zero and saturate the region.
QualityMapRequest regionDifferenceMapRequest(const RunComparison& comparison, const Trajectory& before,
                                             LineRange region);

}  // namespace isurface::vis
