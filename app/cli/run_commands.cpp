// Parsing a command line against a list of commands and running the one it names.
#include <malloc.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>

#include "command.h"
#include "inputs.h"
#include "isurface/base/diagnostic.h"
#include "isurface/base/input_files.h"
#include "isurface/io/output_transaction.h"
#include "output_options.h"

namespace isurface::cli {

namespace {

// A command runs once and ends, and `optimize` simulates the whole program once per candidate,
// each run allocating and freeing channels of a hundred megabytes. Taken from fresh mappings,
// every page of them faults in anew, which on a virtual machine took two thirds of `optimize
// --all cameo.nc` (343 s; 117 s with the heap kept): freed memory stays with the process for
// the next candidate (peak 4.35 GB instead of 4.07; 4.5-4.6 GB since the figures and the
// paths' distance are measured on a second thread). A thread's own arena is a mapping of its
// own, given back when it empties: every thread allocates from the one heap.
void keepFreedMemory() {
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, -1);  // never trimmed
  mallopt(M_ARENA_MAX, 1);
}

}  // namespace

int runCommands(int argc, char** argv, const std::vector<Command>& commands) {
  keepFreedMemory();
  CLI::App app{"iSurface: NC interpolation quality maps, headless commands"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "isurface-cli 0.1.0");
  // Option errors read as every other error does ("error: ..."), with the way to the help.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("error: ") + e.what() + "\nRun with --help for more information.\n";
  });
  std::map<CLI::App*, std::function<int()>> runners;
  for (const Command& command : commands) {
    CLI::App* sub = app.add_subcommand(command.name, command.description);
    runners[sub] = command.setup(*sub);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitInputError;
  }
  // A command's files appear all together once it has run, or none of them; no output may
  // replace one of its inputs, nor another of its outputs.
  protectInputFiles(true);
  try {
    OutputTransaction outputs;
    for (auto& [sub, run] : runners) {
      if (!sub->parsed()) continue;
      refuseSharedOutputs(*sub);
      // What it prints (a summary, JSON) says it succeeded: printed once its files are in place.
      HeldStandardOutput printed;
      const int code = run();
      const std::string input = standardOutputInput();  // e.g. a program found in a --batch folder
      if (!input.empty())
        throw InputError(Diagnostic{input, 0, 0, "standard output is this file, an input of this command: what is "
                                                 "printed would be written into it (redirect the output to another file)"});
      outputs.publish();
      // A command that failed on its input (it said why on stderr) has no result to print.
      if (code == kExitInputError) return code;
      // What went to standard output is an output too: on a full disk or a closed pipe it is cut
      // short, and the command has failed, as when a file cannot be written.
      if (!printed.release()) {
        std::fprintf(stderr, "error: cannot write standard output: %s\n", std::strerror(errno));
        return kExitInputError;
      }
      return code;
    }
  } catch (const CommandExit& e) {
    return e.code;
  } catch (const isurface::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kExitInputError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kExitFailure;
  }
  return kExitFailure;
}

}  // namespace isurface::cli
