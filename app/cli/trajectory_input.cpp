#include "trajectory_input.h"

#include <cstdio>
#include <filesystem>

#include "inputs.h"
#include "isurface/io/biip.h"
#include "progress.h"

namespace isurface::cli {

Trajectory readTrajectory(const std::string& biipPath, const TrajectoryChannels& channels) {
  const BiipReader reader(biipPath);
  for (const std::string& w : reader.warnings())
    std::fprintf(stderr, "warning: %s: %s\n", reader.path().c_str(), w.c_str());
  ProgressLine progress("loading " + reader.path());
  Trajectory t = loadTrajectory(reader, [&](double f) { progress.update(f); }, channels);
  progress.finish();
  return t;
}

OpenedRun openRunOnTerminal(const RunFiles& files, const MachineOption& machineOption, bool force,
                            const TrajectoryChannels& channels) {
  OpenRunRequest request;
  request.files = files;
  request.machine = loadMachineOption(machineOption);  // the built-in one, with --max-hours, when none is given
  request.channels = channels;
  request.force = force;
  const std::string& first = files.program.empty() ? files.dump : files.program;
  ProgressLine progress((files.dump.empty() ? "reading and simulating " : "reading ") +
                        std::filesystem::path(first).filename().string());
  OpenedRun run;
  try {
    run = openRun(request, [&](double f) { progress.update(f); });
  } catch (const DumpMismatchError& e) {
    progress.finish();
    Diagnostic d = e.diagnostic();
    d.message += " (--force joins them anyway)";
    throw InputError(d);
  }
  progress.finish();
  for (const std::string& w : run.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return run;
}

}  // namespace isurface::cli
