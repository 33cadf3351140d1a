#pragma once
// Numbers as the window shows them beside a curve or a sample.
#include <cmath>
#include <cstdio>
#include <string>

namespace isurface::app_model {

// A value of a curve as a reader takes it in: below half its `resolution` (the rounding left by
// differencing, 1e-12 mm/s^2 on a straight) shown as 0, large values without an exponent, the
// rest to five digits.
inline std::string readableValue(double v, double resolution = 0) {
  if (!std::isfinite(v)) return "-";
  if (std::fabs(v) < 0.5 * resolution) return "0";
  char text[40];
  std::snprintf(text, sizeof text, std::fabs(v) >= 1e5 ? "%.0f" : "%.5g", v);
  return text;
}

}  // namespace isurface::app_model
