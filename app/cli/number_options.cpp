#include "number_options.h"

#include <cmath>
#include <cstdlib>
#include <string>

#include <fmt/format.h>

namespace isurface::cli {

namespace {

// The value as written, shortened: a 309-digit number is not repeated whole.
std::string shown(const std::string& text) { return text.size() > 40 ? text.substr(0, 37) + "..." : text; }

// "" when `text` is a finite number within the range, else why not.
std::string checkNumber(const std::string& text, double lo, double hi, bool aboveLow, bool whole) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return fmt::format("'{}' is not a number", shown(text));
  if (!std::isfinite(v)) return fmt::format("{} is not a finite number", shown(text));
  if (whole && v != std::floor(v)) return fmt::format("{} is not a whole number", shown(text));
  if (v > hi || v < lo || (aboveLow && v == lo))
    return aboveLow ? fmt::format("{} must be above {:.10g} and at most {:.10g}", shown(text), lo, hi)
                    : fmt::format("{} must be from {:.10g} to {:.10g}", shown(text), lo, hi);
  return "";
}

}  // namespace

CLI::Validator numberFrom(double lo, double hi, bool aboveLow) {
  return CLI::Validator(
      [=](std::string& text) { return checkNumber(text, lo, hi, aboveLow, false); },
      fmt::format("NUMBER {}{:g}..{:g}", aboveLow ? ">" : "", lo, hi));
}

CLI::Validator wholeNumberFrom(double lo, double hi) {
  return CLI::Validator([=](std::string& text) { return checkNumber(text, lo, hi, false, true); },
                        fmt::format("INT {:g}..{:g}", lo, hi));
}

}  // namespace isurface::cli
