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
  double stepShare = 0.015;  // of a pass's programmed feed: the most it may run faster than its neighbour
  double reach = 2.0;        // mm: a pass farther than this from a point is no neighbour of it
};

// `passes`: each pass's ramped feeds, in the order the passes run (a zig-zag's neighbours are
// the passes before and after); `programmedFeeds`: each one's F (mm/min; passes of different
// feeds are different work and do not hold each other). Returns, per pass and per point of it,
// the feed the point may run at (mm/min; infinite where no neighbour is near): its own speed, or
// the neighbours' near it plus a step if lower, and through them the passes' beyond, both ways
// along the passes.
std::vector<std::vector<double>> speedCapsAcrossPasses(const std::vector<FeedPerMove>& passes, const std::vector<double>& programmedFeeds,
                                                       const SpeedsAcrossPasses& rule);

}  // namespace isurface
