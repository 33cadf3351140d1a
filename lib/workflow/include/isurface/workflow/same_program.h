#pragma once
// Whether two runs (dumps, traces) can be of one program: comparing runs of different programs
// line by line gives figures that mean nothing, without a word.
#include <optional>
#include <string>

#include "isurface/base/trajectory.h"

namespace isurface {

// Why `b` cannot be a run of `a`'s program, or nothing when it may be: fewer than half of a's
// samples lie on lines b has, or more than kRunsOffShare of those checked lie farther than
// kJoinDistance from b's samples of the same line (or the lines next to it, which a blend may
// take). Runs without lines are not checked here.
std::optional<std::string> runsMismatch(const Trajectory& a, const Trajectory& b);
constexpr double kRunsOffShare = 0.05;

}  // namespace isurface
