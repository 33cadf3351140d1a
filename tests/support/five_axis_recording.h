#pragma once
// A recording of LinuxCNC 2.9's five-axis planner (../shared/tools/linuxcnc-sim-5axis): one row
// per 1 ms servo cycle with the joints, the axes (tool tip in the table frame, B C) and the line.
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace isurface::test {

struct FiveAxisRow {
  std::array<double, 5> joints{};  // machine X Y Z (mm), B C (deg)
  std::array<double, 5> axes{};    // tip x y z (mm), b c (deg)
  unsigned line = 0;
};

// The rows of a gzipped recording; empty when it cannot be read.
inline std::vector<FiveAxisRow> readFiveAxisRecording(const std::filesystem::path& gz) {
  std::vector<FiveAxisRow> rows;
  FILE* in = popen(("gzip -dc '" + gz.string() + "'").c_str(), "r");
  if (!in) return rows;
  char text[512];
  while (std::fgets(text, sizeof text, in)) {
    std::istringstream row(text);
    double index = 0, line = 0;
    FiveAxisRow r;
    row >> index;
    for (double& v : r.joints) row >> v;
    for (double& v : r.axes) row >> v;
    row >> line;
    r.line = static_cast<unsigned>(line);
    if (row) rows.push_back(r);
  }
  pclose(in);
  return rows;
}

// The recordings (NAME.halsampler.txt.gz) of a folder, by NAME, sorted.
inline std::vector<std::string> recordingNames(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  const std::string suffix = ".halsampler.txt.gz";
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string file = entry.path().filename().string();
    if (file.size() > suffix.size() && file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0)
      names.push_back(file.substr(0, file.size() - suffix.size()));
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace isurface::test
