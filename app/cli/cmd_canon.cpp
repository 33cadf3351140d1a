// `isurface-cli canon`: interprets a G-code program and prints one line per move (docs/canon-format.md).
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "command.h"
#include "inputs.h"
#include "output_options.h"
#include "isurface/io/canon_writer.h"
#include "isurface/workflow/run_inputs.h"
#include "progress.h"

namespace isurface::cli {

namespace {

std::function<int()> setup(CLI::App& sub) {
  struct Args {
    std::string input, output;
    MachineOption machine;
    bool keepGoing = false;
    bool stack = false;
  };
  auto args = std::make_shared<Args>();
  sub.add_option("file", args->input, "G-code program (RS274/NGC)")->required();
  sub.add_flag("--keep-going", args->keepGoing,
               "skip bad blocks, report every error and print all moves that could be made");
  sub.add_flag("--stack", args->stack,
               "after each move made inside subroutine or subprogram calls, ' @ ' and the calls, outermost "
               "first: the line of each call and what it called");
  outputOption(sub.add_option("-o,--output", args->output, "write the moves to this file instead of stdout"));
  args->machine.addTo(sub, "machine description (JSON) whose control reads the program: its dialect, power-on "
                           "units and tools");
  sub.footer("Output: one line per move, `LINE G0|G1 X Y Z F`, `LINE G2|G3 X Y Z CX CY CZ PLANE "
             "TURNS F` or `LINE G4 P<seconds>`, in workpiece mm and mm/min; with --stack, ` @ 12 o<name> > 40 O1000` after "
             "a move made in calls (docs/canon-format.md).");
  return [args]() -> int {
    InterpreterOptions options = interpreterOptions(loadMachineOption(args->machine));
    options.keepGoing = args->keepGoing;
    if (args->stack) options.callStack = [](std::uint64_t, const std::string&) {};  // the writer listens
    ProgressLine progress("canon");
    options.progress = [&progress](double f) { progress.update(f); };
    int code = kExitOk;
    StreamedInterpretation result;
    if (args->output.empty()) {
      int error = 0;
      result = interpretToStdout(args->input, options, error);
      progress.finish();
      if (error != 0) {
        std::fprintf(stderr, "error: cannot write the output: %s\n", std::strerror(error));
        code = kExitInputError;  // as every command that cannot write where it was told to
      }
    } else {
      std::string writeError;
      result = interpretToPath(args->input, options, args->output, writeError);
      progress.finish();
      // Without --keep-going a program with errors is not written at all.
      if (!writeError.empty() && (result.ok() || args->keepGoing)) {
        std::fprintf(stderr, "error: %s\n", writeError.c_str());
        code = kExitInputError;
      }
    }
    if (!result.ok()) code = kExitInputError;
    for (const Diagnostic& w : result.warnings)
      std::fprintf(stderr, "warning: %s\n", w.str().c_str());
    for (const Diagnostic& e : result.errors) std::fprintf(stderr, "error: %s\n", e.str().c_str());
    return code;
  };
}

}  // namespace

Command canonCommand() {
  return Command{"canon", "Interpret a G-code program and print its moves, one line each", setup};
}


}  // namespace isurface::cli
