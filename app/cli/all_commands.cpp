// Every subcommand, those that draw included (they link VTK and OSMesa).
#include <algorithm>

#include "command.h"

namespace isurface::cli {

std::vector<Command> allCommands() {
  std::vector<Command> all = plainCommands();
  for (Command c : {analyzeCommand(), compareCommand(), exportCommand(), optimizeCommand(), renderCommand(), reportCommand(),
                    stsCommand(), uiSnapshotCommand()})
    all.push_back(std::move(c));
  std::sort(all.begin(), all.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
  return all;
}

}  // namespace isurface::cli
