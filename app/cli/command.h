#pragma once
// Every isurface-cli subcommand registers itself here from its own file.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace isurface::cli {

// Adds the subcommand's options to `sub` and returns what runs it; its result is the exit code.
using CommandSetup = std::function<std::function<int()>(CLI::App& sub)>;

// Called from a static initialiser in each command's file.
bool registerCommand(std::string name, std::string description, CommandSetup setup);

// Exit codes shared by all commands.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;     // an I/O or internal failure
constexpr int kExitInputError = 2;  // bad input: malformed file, impossible parameters

}  // namespace isurface::cli
