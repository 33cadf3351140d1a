#pragma once
// The bound on a simulated run's length (the machine's longestRun, --max-hours): a longer run's
// samples would fill the disk or the memory, so it is refused where it passes the bound.
#include <string>

#include "isurface/base/diagnostic.h"
#include "isurface/machine/machine.h"

namespace isurface {

// The error of a run that passes `machine.longestRun` at `line`, `column` of `source` (0: where
// the program ends).
InputError runTooLongError(const Machine& machine, const std::string& source, unsigned line, unsigned column);

}  // namespace isurface
