#pragma once
// Simulating a program into a Biip dump, written atomically; the dump's metadata names the
// program (`source`) and the machine, so that a dump can be checked against its program later.
#include <string>
#include <vector>

#include "isurface/gcode/gcode_stream.h"
#include "isurface/io/biip.h"
#include "isurface/nc/simulator.h"

namespace isurface {

// The channel table of a simulated dump: line, block, x y z, fb_x fb_y fb_z, feed; on a
// machine with rotary axes also its rotary axes (b, c) and joints (joint_x ... joint_c), x y z
// then being the tool tip in the workpiece frame.
std::vector<BiipChannel> simulationChannels(const Machine& machine);

// Simulates into a Biip file written atomically (nothing is left at `path` on failure).
SimulationReport simulateToBiip(const Program& program, const Machine& machine, const std::string& path,
                                const ProgressCallback& progress = {});

struct StreamedSimulation {
  StreamedInterpretation interpretation;  // when it has errors, nothing was written
  SimulationReport report;
  std::size_t largestWindow = 0;          // segments the planner held at most
  std::size_t forcedCommits = 0;
};

// Interprets and simulates a G-code file in bounded memory (interpretGcodeFileStream into a
// StreamingSimulation) into a Biip file written atomically: nothing is left at `biipPath` when
// the program has errors (returned, not thrown) or planning fails (InputError), or the run
// passes the machine's longest run (InputError: the interpretation stops there). A regular file
// is read once before it is simulated, so that its errors (a program that never ends among them)
// come before any sample. Progress: the fraction of the G-code read while simulating.
StreamedSimulation simulateGcodeFileToBiip(const std::string& gcodePath, const Machine& machine,
                                           const std::string& biipPath, const InterpreterOptions& options = {});

}  // namespace isurface
