#include "trajectory_input.h"

#include <cstdio>

#include "isurface/io/biip.h"
#include "isurface/workflow/run_inputs.h"
#include "progress.h"

namespace isurface::cli {

namespace {

Trajectory load(const BiipReader& reader, const TrajectoryChannels& channels) {
  for (const std::string& w : reader.warnings())
    std::fprintf(stderr, "warning: %s: %s\n", reader.path().c_str(), w.c_str());
  ProgressLine progress("loading " + reader.path());
  Trajectory t = loadTrajectory(reader, [&](double f) { progress.update(f); }, channels);
  progress.finish();
  return t;
}

}  // namespace

Trajectory readTrajectory(const std::string& biipPath, const TrajectoryChannels& channels) {
  return load(BiipReader(biipPath), channels);
}

Trajectory readProgramDump(const std::string& biipPath, const Program& program, bool force,
                           const TrajectoryChannels& channels) {
  const BiipReader reader(biipPath);
  Trajectory samples = load(reader, channels);
  if (!force)
    if (const auto why = dumpMismatch(reader, samples, program))
      throw InputError(Diagnostic{biipPath, 0, 0,
                                  "is not a dump of " + program.source + ": " + *why + " (--force joins them anyway)"});
  return samples;
}

Trajectory simulateTrajectory(const Program& program, const Machine& machine) {
  ProgressLine progress("simulating " + program.source);
  Trajectory samples = simulateRun(program, machine, [&](double f) { progress.update(f); });
  progress.finish();
  return samples;
}

}  // namespace isurface::cli
