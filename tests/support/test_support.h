#pragma once
// Helpers shared by the test suites: paths to inputs and running the command-line tool.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace isurface::test {

inline std::string sourcePath(const std::string& relative) {
  return std::string(ISURFACE_SOURCE_DIR) + "/" + relative;
}
inline std::string realdataPath(const std::string& name) {
  return std::string(ISURFACE_SHARED_DIR) + "/realdata/" + name;
}
inline bool fileExists(const std::string& path) { return std::filesystem::exists(path); }

inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh scratch folder per test binary run.
inline std::filesystem::path scratchDir() {
  static std::filesystem::path dir = [] {
    char tmpl[] = "/tmp/isurface-test-XXXXXX";
    const char* made = mkdtemp(tmpl);
    return std::filesystem::path(made ? made : "/tmp");
  }();
  return dir;
}

#ifdef ISURFACE_CLI  // only tests/cli runs the command line
struct CommandResult {
  int exitCode = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Runs a shell command line, its output captured.
inline CommandResult runShell(const std::string& commandLine) {
  static int counter = 0;
  const auto base = scratchDir() / ("cli" + std::to_string(counter++));
  const std::string outPath = base.string() + ".out", errPath = base.string() + ".err";
  const std::string command = "(" + commandLine + ") >" + outPath + " 2>" + errPath + " </dev/null";
  const int status = std::system(command.c_str());
  CommandResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readFile(outPath);
  r.err = readFile(errPath);
  return r;
}

// Runs isurface-cli with the given argument string (shell syntax).
inline CommandResult runCli(const std::string& args) { return runShell(std::string(ISURFACE_CLI) + " " + args); }
#endif

}  // namespace isurface::test
