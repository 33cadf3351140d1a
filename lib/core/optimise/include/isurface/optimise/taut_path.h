#pragma once
// A pass's points drawn taut inside a tube around them: every point but the two ends moves, by
// at most `radius` (mm), toward the chord between its neighbours. A relief sampled by a CAM system
// with points that step up and down by tens of micrometres (a zig-zag the tool follows at every
// point) keeps its shape but turns less at each point, so a jerk-limited machine brakes less.
// The new polyline lies within `radius` of the old one: each point stays in its ball and every
// segment between two points in their balls stays within the same distance of the old segment.
#include <vector>

#include "isurface/base/geometry.h"

namespace isurface {

std::vector<Vec3> drawnTaut(const std::vector<Vec3>& points, double radius);

}  // namespace isurface
