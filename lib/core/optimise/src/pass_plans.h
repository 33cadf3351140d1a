#pragma once
// Every pass of a region re-fitted and its interval feeds planned (the paper's steps, pass by
// pass); region_optimizer.cpp then plans the feeds across passes and writes the passes.
#include <cstddef>
#include <vector>

#include "isurface/gcode/program.h"
#include "isurface/machine/machine.h"
#include "isurface/optimise/cross_pass_feeds.h"
#include "isurface/optimise/region_optimizer.h"

namespace isurface {

// Where the path was re-fitted: dense, curved intervals (the transition a region is about,
// not its long straight runs), mm.
struct FittedBox {
  bool empty = true;
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();
  void add(const Vec3& p) {
    lower = empty ? p : lower.cwiseMin(p);
    upper = empty ? p : upper.cwiseMax(p);
    empty = false;
  }
};

// `runs`: per pass, its moves (indices into program.moves). `fitted` takes in every pass's
// dense, curved intervals.
std::vector<PassFeeds> planPasses(const Program& program, const std::vector<std::vector<std::size_t>>& runs,
                                  const Machine& machine, const OptimizeOptions& options, FittedBox& fitted);

}  // namespace isurface
