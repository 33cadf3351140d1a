#pragma once
// Dumps the workflow and application tests open: simulated from the bundled samples, with the
// default machine or a slower one, written once per test binary run.
#include <string>

#include "isurface/io/trajectory_writing.h"
#include "isurface/workflow/run_inputs.h"
#include "isurface/workflow/simulation_dump.h"
#include "test_support.h"

namespace isurface::test {

// A machine far from the default: half the acceleration and jerk, a 2 ms cycle.
inline Machine slowMachine() {
  Machine m = defaultMachine();
  m.name = "slow test machine";
  m.cycle = 0.002;
  for (AxisLimits& a : m.axes) a.maxAcceleration *= 0.5, a.maxJerk *= 0.5;
  return m;
}

// samples/<name>.nc simulated with `machine` into the scratch folder (once per name and tag).
inline std::string simulatedDump(const std::string& name, const Machine& machine, const std::string& tag) {
  const std::string path = (scratchDir() / (name + "-" + tag + ".biip")).string();
  if (!fileExists(path)) simulateToBiip(readProgram(sourcePath("samples/" + name + ".nc")), machine, path);
  return path;
}

inline std::string transitionDump() { return simulatedDump("transition-surface", defaultMachine(), "default"); }

}  // namespace isurface::test
