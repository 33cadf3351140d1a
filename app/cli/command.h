#pragma once
// The isurface-cli subcommands: each file cmd_NAME.cpp makes one; commands.cpp lists them.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace isurface::cli {

// Adds the subcommand's options to `sub` and returns what runs it; its result is the exit code.
using CommandSetup = std::function<std::function<int()>(CLI::App& sub)>;

struct Command {
  std::string name, description;
  CommandSetup setup;
};

// With a painter, `analyze --png` draws the map (in isurface-cli-all); without, the command
// draws nothing and needs no VTK.
struct AnalysisPicture;
using AnalysisPainter = void (*)(const AnalysisPicture& picture);
Command analyzeCommand(AnalysisPainter painter = nullptr);
Command canonCommand();
Command compareCommand();
Command exportCommand();
Command fitCommand();
Command importCommand();
Command infoCommand();
Command intervalsCommand();
Command locateCommand();
Command optimizeCommand();
Command renderCommand();
Command reportCommand();
Command sampleCommand();
Command simulateCommand();
Command stsCommand();
Command uiSnapshotCommand();

// The commands that draw nothing (no VTK, no OpenGL), and every command, in the order
// `isurface-cli --help` lists them.
std::vector<Command> plainCommands();
std::vector<Command> allCommands();

// Whether the command line asks for a picture (render, compare, analyze --png, ...):
// isurface-cli hands those to isurface-cli-all.
bool drawsPictures(int argc, char** argv);

// Parses the command line against `commands` and runs the one it names; the exit code.
int runCommands(int argc, char** argv, const std::vector<Command>& commands);

// Exit codes shared by all commands.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;     // an I/O or internal failure
constexpr int kExitInputError = 2;  // bad input: malformed file, impossible parameters

}  // namespace isurface::cli
