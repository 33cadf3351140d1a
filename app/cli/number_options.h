#pragma once
// Number options that refuse what they cannot mean: a value that is not a number, NaN, an
// infinity or a value outside the option's range is an error naming the option and the value
// as written (exit 2), never read as something else.
#include <CLI/CLI.hpp>

namespace isurface::cli {

// A number from `lo` to `hi` (above `lo` when `aboveLow`).
CLI::Validator numberFrom(double lo, double hi, bool aboveLow = false);
// A whole number from `lo` to `hi`.
CLI::Validator wholeNumberFrom(double lo, double hi);

}  // namespace isurface::cli
