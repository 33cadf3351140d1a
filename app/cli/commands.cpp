// The lists of isurface-cli's subcommands.
#include <algorithm>

#include "command.h"

namespace isurface::cli {

std::vector<Command> plainCommands() {
  return {analyzeCommand(),   canonCommand(),  exportCommand(), fitCommand(),    importCommand(), infoCommand(),
          intervalsCommand(), locateCommand(), sampleCommand(), simulateCommand()};
}

bool drawsPictures(int argc, char** argv) {
  static const char* const kDrawing[] = {"compare", "optimize", "render", "report", "sts", "ui-snapshot"};
  std::string command;
  bool png = false;
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (command.empty() && word[0] != '-') command = word;
    png |= word.rfind("--png", 0) == 0;
  }
  if (command == "analyze") return png;
  return std::find(std::begin(kDrawing), std::end(kDrawing), command) != std::end(kDrawing);
}

}  // namespace isurface::cli
