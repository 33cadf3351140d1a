#pragma once
// Splitting interpolation samples into cutting passes, for the three kinds of tool path of the
// paper's Figure 1: direction-parallel (raster, zig-zag or one-way), contour-parallel (closed
// loops, waterline levels, spirals) and paths with no boundary (cut by cumulative distance).
#include <cstddef>
#include <string>
#include <vector>

#include "isurface/gcode/program.h"
#include "isurface/base/trajectory.h"

namespace isurface {

enum class PathPattern { Auto, DirectionParallel, ContourParallel, NoBoundary };

const char* pathPatternName(PathPattern pattern);  // "direction-parallel", ...
// The pattern of that name; InputError naming `option` and the known names otherwise.
PathPattern parsePathPattern(const std::string& name, const std::string& option = "--pattern");

struct Pass {
  std::size_t begin = 0, end = 0;  // samples [begin, end)
  std::size_t size() const { return end - begin; }
};

struct PassSet {
  PathPattern pattern = PathPattern::NoBoundary;  // as detected or asked for
  std::vector<Pass> passes;                        // in program order
};

struct PassOptions {
  PathPattern pattern = PathPattern::Auto;
  // The program, when known, tells rapids and feed moves apart (by the block or line channel).
  const Program* program = nullptr;
  double minimumPassLength = 2.0;       // mm; shorter cutting runs (links, step-overs) are left out
  double noBoundaryDistance = 50.0;     // mm of path per pass for paths with no boundary
};

// Leaves out what does not cut (rapids, plunges and retracts, air moves; see passes.cpp) and
// splits the rest by pattern. Auto takes
//   - direction-parallel when at least 70% of the cutting path lies in two or more passes that
//     are straight in XY and parallel to the main direction of motion (a pass is a stretch
//     moving one way along that direction; reversals and step-overs across it end passes);
//   - else contour-parallel when at least half of it lies in complete turns (the horizontal
//     heading turns through 360 degrees and the path comes back nearest its start: a closed
//     loop, or a spiral's revolution), one pass per turn, links between loops left out;
//   - else no boundary: a pass every noBoundaryDistance mm of path.
// Passes never share samples.
PassSet splitPasses(const Trajectory& samples, const PassOptions& options = {});

}  // namespace isurface
