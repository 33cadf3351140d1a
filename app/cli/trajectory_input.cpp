#include "trajectory_input.h"

#include <cstdio>

#include "isurface/io/biip.h"
#include "isurface/nc/simulator.h"
#include "isurface/io/trajectory_loading.h"
#include "isurface/nc/sample_trajectory.h"
#include "progress.h"

namespace isurface::cli {

Trajectory readTrajectory(const std::string& biipPath, const TrajectoryChannels& channels) {
  const BiipReader reader(biipPath);
  for (const std::string& w : reader.warnings()) std::fprintf(stderr, "warning: %s: %s\n", biipPath.c_str(), w.c_str());
  ProgressLine progress("loading " + biipPath);
  Trajectory t = loadTrajectory(reader, [&](double f) { progress.update(f); }, channels);
  progress.finish();
  return t;
}

Trajectory simulateTrajectory(const Program& program, const Machine& machine) {
  ProgressLine progress("simulating " + program.source);
  SampleBuffer buffer;
  simulate(program, machine, buffer, [&](double f) { progress.update(f); });
  progress.finish();
  return trajectoryFromSamples(buffer.data, machine.cycle, program.source);
}

}  // namespace isurface::cli
