#pragma once
// Feed limits learnt from a candidate's simulated run, for the candidates that follow it in the
// closed loop (region_optimisation.cpp).
#include <vector>

#include "isurface/workflow/region_optimisation.h"

namespace isurface {

// Feed ceilings (mm/min per old source line) that bring the servo's deviation in a candidate's
// run back to `targetUm`: a move whose samples deviate by d > target is held to its feed times
// sqrt(target / d) (the lag that deviates the path grows with the square of the speed where it
// bends), with a margin. `previous` ceilings are kept where they are lower.
std::vector<double> deviationCeilings(const RegionOptimisation& r, double targetUm, std::vector<double> previous);

// mm/min: the feed caps of the candidates after `r`, from the fastest down: the speeds its run
// exceeds on 1, 10, 30 and 50 % of its surface samples in the region (its briefest peaks first,
// then ever more of its speeds), but for those within 1 % of the region's highest feed (they
// would change nearly nothing) or below 1 mm/min. A program whose feed is a placeholder far
// above what the machine reaches gets caps far below it.
std::vector<double> speedPeakCaps(const RegionOptimisation& r);

}  // namespace isurface
