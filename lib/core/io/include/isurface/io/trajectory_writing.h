#pragma once
// Writing samples made in memory (not by the simulator) as a Biip dump.
#include <string>

#include "isurface/base/trajectory.h"

namespace isurface {

// Channels: line, x y z, t, feedback and feed when present, and every extra channel (f64).
void writeTrajectoryBiip(const Trajectory& samples, const std::string& path);

}  // namespace isurface
