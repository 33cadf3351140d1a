#pragma once
// The simulator's samples as a Trajectory, for analysis in memory.
#include <string>
#include <vector>

#include "isurface/base/trajectory.h"
#include "isurface/nc/interpolator.h"

namespace isurface {

// rapidFeed is left 0: set it from the machine when the caller knows it.
Trajectory trajectoryFromSamples(const std::vector<SimSample>& samples, double cycle, const std::string& source);

}  // namespace isurface
