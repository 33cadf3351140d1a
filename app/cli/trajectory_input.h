#pragma once
// The samples a command works on: read from a Biip dump or simulated from the program, with a
// progress line on the terminal.
#include <string>

#include "isurface/machine/machine.h"
#include "isurface/gcode/program.h"
#include "isurface/base/trajectory.h"
#include "isurface/io/trajectory_loading.h"

namespace isurface::cli {

Trajectory readTrajectory(const std::string& biipPath, const TrajectoryChannels& channels = {});
Trajectory simulateTrajectory(const Program& program, const Machine& machine);

}  // namespace isurface::cli
