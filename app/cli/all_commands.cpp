// Every subcommand, those that draw included (they link VTK and OSMesa).
#include <algorithm>

#include "analysis_picture.h"
#include "command.h"

namespace isurface::cli {

std::vector<Command> allCommands() {
  std::vector<Command> all = plainCommands();
  // analyze as the plain one, and drawing its --png.
  all.erase(std::remove_if(all.begin(), all.end(), [](const Command& c) { return c.name == "analyze"; }), all.end());
  for (Command c : {analyzeCommand(&paintAnalysis), compareCommand(), optimizeCommand(), renderCommand(), reportCommand(),
                    stsCommand(), uiSnapshotCommand()})
    all.push_back(std::move(c));
  std::sort(all.begin(), all.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
  return all;
}

}  // namespace isurface::cli
