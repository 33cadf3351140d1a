#pragma once
// Writing samples made in memory (not by the simulator) as a Biip dump.
#include <string>

#include "isurface/base/trajectory.h"

namespace isurface {

// Channels: line, x y z, t, feedback and feed when present, and every extra channel (f64).
// `machineJson`: the description of the machine that made the samples, kept in the metadata (a
// dump that names its machine is judged with it when read again); empty when none is known.
void writeTrajectoryBiip(const Trajectory& samples, const std::string& path, const std::string& machineJson = "");

}  // namespace isurface
