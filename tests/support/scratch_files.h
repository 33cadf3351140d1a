#pragma once
// Writing a small input file into the scratch folder of the test run.
#include <filesystem>
#include <fstream>
#include <string>

#include "test_support.h"

namespace isurface::test {

// Writes `content` byte for byte to scratchDir()/name and returns the path.
inline std::string writeScratch(const std::string& name, const std::string& content) {
  const std::string path = (scratchDir() / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// An empty folder scratchDir()/name (emptied when it is there).
inline std::filesystem::path freshScratchFolder(const std::string& name) {
  const std::filesystem::path folder = scratchDir() / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

// Writes `content` byte for byte to `path`.
inline void writeFileBytes(const std::filesystem::path& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
}

// `path` in single quotes, for a command line run by the shell.
inline std::string shellQuoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

}  // namespace isurface::test
