// isurface-cli simulate: G-code -> Biip dump through the NC interpolator model.
#include <cstdio>
#include <nlohmann/json.hpp>

#include "command.h"
#include "output_options.h"
#include "inputs.h"
#include "isurface/nc/simulator.h"
#include "isurface/workflow/run_inputs.h"
#include "isurface/workflow/simulation_dump.h"
#include "progress.h"
#include "isurface/base/json_text.h"

namespace isurface::cli {
namespace {

struct SimulateOptions {
  std::string input, output;
  MachineOption machine;
  bool keepGoing = false, json = false;
};

int runSimulate(const SimulateOptions& o) {
  const Machine machine = loadMachineOption(o.machine);
  ProgressLine progress("simulating " + o.input);
  InterpreterOptions options = interpreterOptions(machine);
  options.keepGoing = o.keepGoing;
  options.progress = [&](double f) { progress.update(f); };
  // Interpreted, planned and interpolated as the file is read: memory does not grow with it.
  const StreamedSimulation s = simulateGcodeFileToBiip(o.input, machine, o.output, options);
  progress.finish();
  for (const Diagnostic& w : s.interpretation.warnings) std::fprintf(stderr, "warning: %s\n", w.str().c_str());
  for (const Diagnostic& e : s.interpretation.errors) std::fprintf(stderr, "error: %s\n", e.str().c_str());
  if (!s.interpretation.ok()) return kExitInputError;
  if (s.forcedCommits > 0)
    std::fprintf(stderr,
                 "warning: %zu times the look-ahead window filled up with tiny moves before the speed was "
                 "settled: the tool slows down there more than planning the whole program would\n",
                 s.forcedCommits);
  const SimulationReport& r = s.report;
  for (const Diagnostic& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.str().c_str());
  const auto moves = static_cast<unsigned long long>(s.interpretation.moveCount);
  if (o.json) {
    nlohmann::json j = {{"source", o.input},          {"output", o.output},
                        {"moves", moves},             {"motion_segments", r.segments},
                        {"samples", r.samples},        {"cycle_s", machine.cycle},
                        {"machining_time_s", r.machiningTime}, {"path_length_mm", r.pathLength},
                        {"jerk_filter_s", r.filterTime1}, {"corner_filter_s", r.filterTime2}};
    std::printf("%s\n", jsonText(j, 2).c_str());
  } else {
    std::printf("%s: %llu moves, %.1f mm of path\n", o.input.c_str(), moves, r.pathLength);
    std::printf("machining time %s (%.3f s), %llu samples at %g ms -> %s\n",
                formatDuration(r.machiningTime).c_str(), r.machiningTime,
                static_cast<unsigned long long>(r.samples), machine.cycle * 1000.0, o.output.c_str());
  }
  return kExitOk;
}

}  // namespace

Command simulateCommand() {
  return Command{"simulate", "Simulate the NC interpolator on a G-code program and write a Biip dump",
    [](CLI::App& sub) {
      auto o = std::make_shared<SimulateOptions>();
      sub.add_option("program", o->input, "G-code file")->required();
      outputOption(sub.add_option("-o,--output", o->output, "Biip file to write"))->required();
      o->machine.addTo(sub, "machine description (JSON); default: built-in");
      sub.add_flag("--keep-going", o->keepGoing, "report every bad block, not only the first");
      sub.add_flag("--json", o->json, "print the summary as JSON");
      return [o] { return runSimulate(*o); };
    }};
}

}  // namespace isurface::cli
