#pragma once
// Of a pass (a run of moves), the stretch that crosses a box: what is re-planned of it when a
// region is asked for by its box (OptimizeOptions::planBox).
#include <cstddef>
#include <utility>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/gcode/program.h"

namespace isurface {

// `run`: indices of consecutive moves of `program`; `box`: XY, mm. From the first move whose
// extent along the run (its direction from its first point to its last, seen from above)
// reaches into the box's, widened by 2 mm, to the last such move, and on to the straights
// around (moves of 4 mm or more): a bend re-planned in part would keep a corner where the new
// path meets the old. Empty when no move reaches into it; the whole run when it has no
// direction (it ends where it began).
std::vector<std::size_t> stretchAcrossBox(const Program& program, const std::vector<std::size_t>& run,
                                          const std::pair<Vec3, Vec3>& box);

}  // namespace isurface
