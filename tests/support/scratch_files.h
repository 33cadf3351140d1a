#pragma once
// Writing a small input file into the scratch folder of the test run.
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

}  // namespace isurface::test
