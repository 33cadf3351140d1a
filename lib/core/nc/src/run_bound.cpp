#include "isurface/nc/run_bound.h"

#include <fmt/format.h>

namespace isurface {

InputError runTooLongError(const Machine& machine, const std::string& source, unsigned line, unsigned column) {
  return InputError(Diagnostic{
      source, line, column,
      fmt::format("the run passes {:.4g} h of machining here ({:.4g} samples at {:g} ms): a longer run is refused "
                  "(raise --max-hours to simulate it)",
                  machine.longestRun / 3600, machine.longestRun / machine.cycle, machine.cycle * 1000)});
}

}  // namespace isurface
