// The lists of isurface-cli's subcommands.
#include <algorithm>

#include "command.h"

namespace isurface::cli {

std::vector<Command> plainCommands() {
  return {canonCommand(),     fitCommand(),    importCommand(), infoCommand(),
          intervalsCommand(), locateCommand(), sampleCommand(), simulateCommand()};
}

bool drawsPictures(const std::string& command) {
  static const char* const kDrawing[] = {"analyze", "compare", "export", "optimize", "render", "report", "sts", "ui-snapshot"};
  return std::find(std::begin(kDrawing), std::end(kDrawing), command) != std::end(kDrawing);
}

}  // namespace isurface::cli
