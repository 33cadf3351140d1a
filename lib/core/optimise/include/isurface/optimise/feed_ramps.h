#pragma once
// The interval feeds of a re-fitted pass as one feed per G1 move, with the changes between
// intervals spread into ramps of gentle acceleration. A step from one interval's feed to the
// next is a jerk-limited change over a few milliseconds: the speed's fluctuation about its
// moving average and the jerk come from such steps. A ramp laid out along the path (long moves
// cut where the feed changes by a step) changes the speed evenly instead, and, being a
// function of the position on the path, is the same whichever way a pass runs: a pass and its
// neighbour cut the other way slow down over the same stretch of the surface.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/optimise/cross_pass_feeds.h"

namespace isurface {

struct FeedPerMove {
  std::vector<Vec3> points;                 // the pass's points, long moves cut where a ramp crosses them
  std::vector<std::uint32_t> sourceLines;   // per point after the first, the old line it stands for
  std::vector<double> feeds;                // per move (point k to k + 1), mm/min
  std::vector<std::size_t> passPointAt;     // per point of the pass (PassFeeds), its index in `points`
};

struct RampOptions {
  double programmedFeed = 0;    // mm/min, the pass's F: the feed of a pass with no intervals
  // mm/s^2: no point is passed faster than sqrt(limit / curvature) (one over the radius of the
  // circle through it and its neighbours; a turn beside a move under a micrometre, rounding in
  // the program's digits, is no bend): a move runs no faster than its gentler end allows, the
  // ramp from its sharper end covering the rest; 0: no limit.
  // Taken at every point rather than per interval: where a bend is, and so how fast it may be
  // run, does not depend on which way a pass runs, as the interval boundaries do. No move is
  // slowed below a fifth of the programmed feed, as no interval is.
  double normalAccelerationLimit = 0;
  double rampAcceleration = 0;  // mm/s^2, the ramps' tangential acceleration; 0: steps
  // XY, mm: the ramps run at rampAcceleration on the moves that reach inside, and at
  // outsideAcceleration (if faster) on the others. None: rampAcceleration everywhere.
  std::optional<std::pair<Vec3, Vec3>> within;
  double outsideAcceleration = 0;  // mm/s^2
};

// No move's feed is above its interval's; a ramp lies in the faster stretch and changes the
// feed by 1 % of the programmed feed from one move to the next. Ramps are cut at whole
// multiples of that step, so that neighbouring passes whose ramps differ a little still share
// their feeds.
FeedPerMove feedPerMove(const PassFeeds& pass, const RampOptions& options);

// The same pass again, `ramped` (its feedPerMove) held at each of its points to `caps` (mm/min,
// one per point of `ramped`; speeds_across_passes.h): the ramps lead into every cap, the bends
// keep the curvature they had, and a move keeps the ramps' acceleration it had.
FeedPerMove feedPerMoveHeldTo(const PassFeeds& pass, const FeedPerMove& ramped, const std::vector<double>& caps,
                              const RampOptions& options);

}  // namespace isurface
