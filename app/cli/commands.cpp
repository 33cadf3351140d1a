// The list of isurface-cli's subcommands.
#include "command.h"

namespace isurface::cli {

std::vector<Command> allCommands() {
  return {analyzeCommand(), canonCommand(), compareCommand(), exportCommand(), fitCommand(), importCommand(), infoCommand(), intervalsCommand(), locateCommand(), optimizeCommand(), renderCommand(), sampleCommand(), simulateCommand(), stsCommand(), uiSnapshotCommand()};
}

}  // namespace isurface::cli
