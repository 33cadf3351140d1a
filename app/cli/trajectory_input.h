#pragma once
// The samples a command works on: read from a Biip dump or simulated from the program, with a
// progress line on the terminal.
#include <string>

#include "isurface/gcode/program.h"
#include "isurface/io/trajectory_loading.h"
#include "isurface/machine/machine.h"

namespace isurface::cli {

Trajectory readTrajectory(const std::string& biipPath, const TrajectoryChannels& channels = {});
// A dump given with its program: refused (InputError naming both) when it does not belong to
// it (workflow's dumpMismatch), unless `force`.
Trajectory readProgramDump(const std::string& biipPath, const Program& program, bool force,
                           const TrajectoryChannels& channels = {});
Trajectory simulateTrajectory(const Program& program, const Machine& machine);

}  // namespace isurface::cli
