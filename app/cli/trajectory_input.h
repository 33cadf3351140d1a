#pragma once
// What a command works on, opened through the workflow (a program, its dump or both, or the
// program simulated) with its warnings and a progress line on the terminal.
#include <string>

#include "inputs.h"
#include "isurface/io/trajectory_loading.h"
#include "isurface/workflow/run_inputs.h"

namespace isurface::cli {

// A dump alone (no program), e.g. a machine trace.
Trajectory readTrajectory(const std::string& biipPath, const TrajectoryChannels& channels = {});

// `machineOption` is what --machine and --tool-table gave (none: the default machine); it is used when
// there is no dump to read. A dump refused as another program's names --force in its message.
OpenedRun openRunOnTerminal(const RunFiles& files, const MachineOption& machineOption, bool force,
                            const TrajectoryChannels& channels = {});

}  // namespace isurface::cli
