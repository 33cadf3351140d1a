// A simulated sample names the line whose programmed segment it lies on: where blocks meet,
// the filters' average falls on the next (or the previous) segment for a cycle or two, and a
// pick there must not name the wrong line.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/gcode/path_segment.h"
#include "isurface/machine/machine.h"
#include "isurface/nc/simulator.h"

using namespace isurface;

namespace {

// A zig-zag raster over a wavy surface (2 mm moves) and a row of arcs, at F3000.
std::string rasterWithArcs() {
  std::string text = "G21 G90 G17\nG0 X0 Y0 Z1\nG1 Z0 F3000\n";
  for (int row = 0; row < 12; ++row) {
    const double y = row * 0.5;
    for (int k = 0; k <= 20; ++k) {
      const double x = (row % 2 == 0 ? k : 20 - k) * 2.0;
      char block[96];
      std::snprintf(block, sizeof block, "G1 X%.3f Y%.3f Z%.4f\n", x, y, 0.3 * std::sin(x / 5) * std::cos(y / 3));
      text += block;
    }
  }
  text += "G1 X0 Y8 Z0\n";
  for (int k = 0; k < 10; ++k) text += (k % 2 ? "G2" : "G3") + std::string(" X") + std::to_string(4 * (k + 1)) + " Y8 R2.5\n";
  return text + "M2\n";
}

}  // namespace

TEST(LineLabels, NoSampleLiesNearerAnotherLinesSegmentThanItsOwn) {
  const InterpretResult r = interpretGcode(rasterWithArcs(), "labels.nc");
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  std::multimap<std::uint32_t, PathSegment> segmentsOfLine;
  std::vector<std::uint32_t> lines;  // in program order
  for (std::size_t m = 0; m < r.program.moves.size(); ++m) {
    if (!r.program.moves[m].isMotion()) continue;
    segmentsOfLine.emplace(r.program.moves[m].line, PathSegment::from(r.program, m));
    if (lines.empty() || lines.back() != r.program.moves[m].line) lines.push_back(r.program.moves[m].line);
  }
  const auto distanceToLine = [&](std::uint32_t line, const Vec3& p) {
    double best = std::numeric_limits<double>::infinity();
    for (auto [it, end] = segmentsOfLine.equal_range(line); it != end; ++it) best = std::min(best, it->second.nearest(p).distance);
    return best;
  };
  SampleBuffer buffer;
  simulate(r.program, defaultMachine(), buffer);
  std::size_t checked = 0, nearerAnother = 0;
  double worst = 0;
  for (const SimSample& s : buffer.data) {
    const auto at = std::find(lines.begin(), lines.end(), s.line);
    if (at == lines.end()) continue;
    const Vec3 p(s.x, s.y, s.z);
    const double own = distanceToLine(s.line, p);
    ++checked;
    for (const auto neighbour : {at - 1, at + 1}) {
      if (neighbour < lines.begin() || neighbour >= lines.end()) continue;
      const double other = distanceToLine(*neighbour, p);
      if (other + 0.001 < own) {
        ++nearerAnother;
        worst = std::max(worst, own - other);
        break;
      }
    }
  }
  EXPECT_GT(checked, 10000u);
  EXPECT_EQ(nearerAnother, 0u) << "of " << checked << " samples; worst by " << worst << " mm";
}
