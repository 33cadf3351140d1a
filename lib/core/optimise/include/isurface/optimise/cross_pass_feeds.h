#pragma once
// Interval feeds planned over the surface rather than pass by pass: neighbouring passes over
// the same stretch of the part get the same speed.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/optimise/region_optimizer.h"

namespace isurface {

// One re-fitted pass: its new points and, per constant speed interval, the index of its last
// point and its feed (mm/min).
struct PassFeeds {
  std::vector<Vec3> points;
  std::vector<std::uint32_t> sourceLines;  // per point after the first, the old line it stands for
  std::vector<std::size_t> intervalEnd;
  std::vector<double> feeds;
};

// Applies `rule` to every interval. "Around" an interval: the intervals crossing the cells it
// crosses, or a cell next to one, on a grid over XY whose cells are about one and a half pass
// spacings wide (so the passes on either side always count); the feed an interval gets is the
// lowest, over its cells, of the rule's value there. Feeds are mm/min; none rises.
void harmonizeFeedsAcrossPasses(std::vector<PassFeeds>& passes, CrossPassRule rule);

}  // namespace isurface
