#pragma once
// Inside splitPasses: which samples cut, and how cutting runs are divided into passes for each
// tool-path pattern.
#include <cstddef>
#include <vector>

#include "isurface/surface/passes.h"

namespace isurface::passes_detail {

// Maximal runs of cutting samples, in program order.
std::vector<Pass> cuttingRuns(const Trajectory& samples, const PassOptions& options);

// How well a pattern's passes fit the samples, for choosing one in PathPattern::Auto.
struct PatternFit {
  double cuttingLength = 0;  // mm of path in the cutting runs
  double fittingLength = 0;  // mm of path in passes that look like the pattern
  std::size_t fittingPasses = 0;
  double fraction() const { return cuttingLength > 0 ? fittingLength / cuttingLength : 0; }
};

// Direction-parallel: a pass is a stretch that moves one way along the main raster axis.
// Fitting passes are straight in XY and parallel to the axis.
std::vector<Pass> splitDirectionParallel(const Trajectory& samples, const std::vector<Pass>& runs,
                                         const PassOptions& options, PatternFit* fit = nullptr);

// Contour-parallel: a pass is one turn of the path (closed loop or spiral revolution), ended
// where the path comes nearest its start; the link to the next loop is left out.
// Fitting passes are complete turns.
std::vector<Pass> splitContourParallel(const Trajectory& samples, const std::vector<Pass>& runs,
                                       const PassOptions& options, PatternFit* fit = nullptr);

// No boundary: each run cut every options.noBoundaryDistance mm of path.
std::vector<Pass> splitNoBoundary(const Trajectory& samples, const std::vector<Pass>& runs,
                                  const PassOptions& options);

// mm of 3D path between samples [begin, end), steps touching a non-finite sample skipped.
double pathLength(const Trajectory& samples, std::size_t begin, std::size_t end);

}  // namespace isurface::passes_detail
