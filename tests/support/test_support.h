#pragma once
// Helpers shared by the test suites: paths to inputs and running the command-line tool.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>

#include "test_locations.h"

namespace isurface::test {

inline std::string sourcePath(const std::string& relative) {
  return std::string(sourceDir()) + "/" + relative;
}
inline std::string realdataPath(const std::string& name) {
  return std::string(sharedDir()) + "/realdata/" + name;
}
inline bool fileExists(const std::string& path) { return std::filesystem::exists(path); }

// Tests that need the real inputs of ../shared/realdata (programs and traces written by others,
// not in the repository) skip with one line naming the folder when it is not beside the clone.
#define ISURFACE_SKIP_WITHOUT_REALDATA(...)                                                          \
  do {                                                                                             \
    for (const std::string& needed : std::initializer_list<std::string>{__VA_ARGS__})              \
      if (!::isurface::test::fileExists(needed))                                                   \
        GTEST_SKIP() << "needs " << needed << " (the real inputs of " << ::isurface::test::sharedDir() \
                     << "/realdata/, not beside this clone)";                                      \
  } while (0)

inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh scratch folder per test process, removed when the process ends (each test runs in a
// process of its own, so a folder left behind per test fills /tmp run after run). Set
// ISURFACE_KEEP_TEST_FILES to keep them for a look after a failure.
class ScratchFolder {
 public:
  ScratchFolder() {
    char tmpl[] = "/tmp/isurface-test-XXXXXX";
    if (const char* made = mkdtemp(tmpl)) path_ = made;
  }
  ~ScratchFolder() {
    if (path_.empty() || std::getenv("ISURFACE_KEEP_TEST_FILES")) return;
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline std::filesystem::path scratchDir() {
  static const ScratchFolder folder;
  if (folder.path().empty()) throw std::runtime_error("cannot make a scratch folder in /tmp");
  return folder.path();
}

#ifdef ISURFACE_TESTS_RUN_CLI  // only tests/cli runs the command line
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
inline CommandResult runCli(const std::string& args) { return runShell(std::string(cliProgram()) + " " + args); }
#endif

}  // namespace isurface::test
