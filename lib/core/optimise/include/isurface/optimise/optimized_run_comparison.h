#pragma once
// Comparing a program's run with the run of its re-optimised version (optimizeRegion). The new
// program numbers its lines differently, so the runs are aligned by groups of lines: each
// re-fitted pass (its old lines, and the new lines that replace them) is one group, and every
// other line is matched with itself shifted by what the passes before it added.
#include <cstdint>
#include <vector>

#include "isurface/optimise/region_optimizer.h"
#include "isurface/analysis/run_comparison.h"

namespace isurface {

// The line keys of RunComparisonOptions for run A (the old program) and run B (the new one),
// in the old program's numbering: a pass (in the new program with the comment naming the lines
// it replaces) under its old first line, any other line under its old number.
struct OptimizedLineKeys {
  std::vector<std::uint32_t> before, after;  // index: line number of that program
};
OptimizedLineKeys optimizedLineKeys(const OptimizeResult& result);

// compareRuns(before, after) aligned by those keys: differences are after minus before, and
// lines and ranges are named by the old program's line numbers.
RunComparison compareOptimizedRuns(const Trajectory& before, const Trajectory& after, const OptimizeResult& result,
                                   RunComparisonOptions options = {});

}  // namespace isurface
