#pragma once
// How the closed loop chooses among the candidates it keeps: by the objective's score, and
// between candidates that do about as well, by the shorter program.
#include "isurface/workflow/region_optimisation.h"

namespace isurface {

// Whether `r` (kept) is a better choice than `best` (kept) for the objective.
bool betterFor(Objective objective, const RegionOptimisation& r, const RegionOptimisation& best);

}  // namespace isurface
