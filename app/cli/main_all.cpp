// isurface-cli-all: every headless job of iSurface, those that draw included. isurface-cli runs
// the others itself and hands these over (see main.cpp).
#include "command.h"

int main(int argc, char** argv) { return isurface::cli::runCommands(argc, argv, isurface::cli::allCommands()); }
