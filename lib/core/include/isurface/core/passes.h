#pragma once
// Splitting interpolation samples into cutting passes, for the three kinds of tool path of the
// paper's Figure 1: direction-parallel (raster, zig-zag or one-way), contour-parallel (closed
// loops, waterline levels, spirals) and paths with no boundary (cut by cumulative distance).
#include <cstddef>
#include <string>
#include <vector>

#include "isurface/core/program.h"
#include "isurface/core/trajectory.h"

namespace isurface {

enum class PathPattern { Auto, DirectionParallel, ContourParallel, NoBoundary };

const char* pathPatternName(PathPattern pattern);  // "direction-parallel", ...

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

PassSet splitPasses(const Trajectory& samples, const PassOptions& options = {});

}  // namespace isurface
