#pragma once
// Loading what commands share: a G-code program (with its diagnostics printed) and a machine.
#include <string>

#include "isurface/base/time_format.h"

#include <CLI/CLI.hpp>

#include "isurface/base/diagnostic.h"
#include "isurface/machine/machine.h"
#include "isurface/gcode/program.h"
#include "isurface/surface/surface_mesh.h"

namespace isurface::cli {

// Thrown when a command must stop with a given exit code after it has said why on stderr.
struct CommandExit {
  int code;
};

// Interprets a G-code file, printing warnings and errors on stderr ("error: file:line:col: ...").
// Any error throws CommandExit{kExitInputError}: with keepGoing, after reporting them all.
Program loadProgram(const std::string& path, bool keepGoing, bool showProgress = true);

// --machine and --tool-table, as the commands that read G-code take them.
struct MachineOption {
  std::string description;  // JSON; empty: the built-in machine
  std::string toolTable;    // LinuxCNC .tbl, in the machine's tool table units (tools.units)
  double maxHours = 100;    // the longest run simulated, h
  bool given() const { return !description.empty() || !toolTable.empty(); }
  void addTo(CLI::App& sub, const std::string& help);
};

// The machine of --machine, or the built-in default when the path is empty.
Machine loadMachineOption(const std::string& path);
// With the tools of --tool-table, when given.
Machine loadMachineOption(const MachineOption& option);

// --gap-limit, as every command that makes a surface takes it: passes further apart than this
// (mm) are not joined by its triangles.
struct GapLimitOption {
  double mm = MeshOptions{}.gapLimit;
  void addTo(CLI::App& sub);
  // mm; InputError naming the option unless it is greater than 0.
  double checked() const;
};

// Checks of option values whose message says the value as it was written ("--pick-sample
// must be 0 or more, got -1"), not CLI11's range of every double.
CLI::Validator atLeastZero();
CLI::Validator greaterThanZero();

// Stops a command on a bad option value, naming the file it was given for.
[[noreturn]] inline void badOption(const std::string& file, const std::string& message) {
  throw InputError(Diagnostic{file, 0, 0, message});
}


}  // namespace isurface::cli
