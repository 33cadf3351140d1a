#include "inputs.h"

#include "number_options.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "command.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/workflow/run_inputs.h"
#include "progress.h"

namespace isurface::cli {

Program loadProgram(const std::string& path, bool keepGoing, bool showProgress) {
  ProgressLine progress("reading " + path);
  InterpreterOptions options;
  options.keepGoing = keepGoing;
  if (showProgress) options.progress = [&](double f) { progress.update(f); };
  InterpretResult result = interpretGcodeFile(path, options);
  progress.finish();
  for (const Diagnostic& w : result.program.warnings) std::fprintf(stderr, "warning: %s\n", w.str().c_str());
  for (const Diagnostic& e : result.errors) std::fprintf(stderr, "error: %s\n", e.str().c_str());
  if (!result.ok()) throw CommandExit{kExitInputError};
  requireMotion(path, result.program.moves.size());
  return std::move(result.program);
}

Machine loadMachineOption(const std::string& path) {
  return path.empty() ? defaultMachine() : loadMachine(path);
}

void MachineOption::addTo(CLI::App& sub, const std::string& help) {
  sub.add_option("--machine", description, help);
  sub.add_option("--tool-table", toolTable,
                 "tool table for cutter radius compensation (LinuxCNC .tbl; its lengths in the machine's "
                 "tools.units, mm unless it says inch)");
  sub.add_option("--max-hours", maxHours,
                 "the longest machining time simulated, h (a longer run is refused: its samples would fill the disk)")
      ->capture_default_str()
      ->check(numberFrom(0, 1e6, true));
}

void GapLimitOption::addTo(CLI::App& sub) {
  // Passes a kilometre apart are not one surface: an infinite gap would join anything to anything.
  sub.add_option("--gap-limit", mm, "mm; passes further apart are not joined into the surface")
      ->capture_default_str()
      ->check(numberFrom(0, 1e6, true));
}

double GapLimitOption::checked() const {
  if (!(mm > 0) || !(mm <= 1e6))
    throw InputError(Diagnostic{"", 0, 0, "the gap limit (--gap-limit) must be greater than 0 mm and at most 1e6 mm"});
  return mm;
}

Machine loadMachineOption(const MachineOption& option) {
  Machine machine = loadMachineOption(option.description);
  if (!option.toolTable.empty()) machine.toolDiameters = readToolTable(option.toolTable, machine.toolTableInch);
  machine.longestRun = option.maxHours * 3600.0;
  return machine;
}


}  // namespace isurface::cli
