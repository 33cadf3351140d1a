// isurface-cli: every headless job of iSurface, one subcommand each. The commands that draw
// (render, analyze --png, ...) run in isurface-cli-all, beside this program: loading VTK, OSMesa and
// the LLVM it brings takes a tenth of a second before main, longer than reading a million-line
// program, so the commands that draw nothing start without them.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "command.h"

namespace {

// The first word that is not an option: the command, if any.
std::string commandOf(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] != '-') return argv[i];
  return "";
}

// isurface-cli-all in the folder of this program.
std::string allCommandsProgram() {
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return "isurface-cli-all";
  std::string path(self, static_cast<std::size_t>(n));
  return path.substr(0, path.rfind('/') + 1) + "isurface-cli-all";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace isurface::cli;
  const std::string command = commandOf(argc, argv);
  const bool version = argc == 2 && std::strcmp(argv[1], "--version") == 0;
  if (version || (!command.empty() && !drawsPictures(argc, argv))) return runCommands(argc, argv, plainCommands());
  // A command that draws, or a question (help, nothing, a command unknown here): the program
  // that knows every command answers.
  const std::string all = allCommandsProgram();
  execv(all.c_str(), argv);
  std::fprintf(stderr, "error: cannot run %s: %s\n", all.c_str(), std::strerror(errno));
  return kExitFailure;
}
