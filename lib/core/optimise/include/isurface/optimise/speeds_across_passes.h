#pragma once
// Ramped feeds made to agree from one pass to the next.
//
// Each pass's bends are eased and ramped on their own, and two neighbouring passes over nearly
// the same stretch of surface can still run it at different speeds: where a CAM system wrote
// one of them with a chord more (its corners gentler) or its fit took another shape. The
// difference is the inconsistency between passes the re-planning sets out to remove. Here no
// point of a pass runs faster than the nearest point of the pass before or after it by more
// than a step; a pass that would is slowed there, and its own ramps then lead into the cap.
#include <vector>

#include "isurface/optimise/feed_ramps.h"

namespace isurface {

struct SpeedsAcrossPasses {
  double step = 0;      // mm/min, the most a point may run faster than its neighbour's
  double reach = 2.0;   // mm: a pass farther than this from a point is no neighbour of it
};

// `passes`: each pass's ramped feeds, in the order the passes run (a zig-zag's neighbours are
// the passes before and after). Returns, per pass and per point of it, the feed the point may
// run at (mm/min; infinite where nothing caps it): its moves' feeds, lowered to the
// neighbours' plus the step, and through them to theirs, both ways along the passes.
std::vector<std::vector<double>> speedCapsAcrossPasses(const std::vector<FeedPerMove>& passes, const SpeedsAcrossPasses& rule);

}  // namespace isurface
