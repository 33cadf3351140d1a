#pragma once
// Lengths, feeds and their derivatives as the window shows them: millimetres, or inches for a
// program written in inches (or when the user says so). Everything is computed in mm and s.
#include <cstddef>
#include <string_view>

#include "isurface/app_model/readable_value.h"
#include "isurface/base/units.h"

namespace isurface::panels {

using app_model::readableValue;

struct DisplayUnits {
  bool inch = false;

  double length(double mm) const { return inch ? mm / kMmPerInch : mm; }  // also per s, s^2, s^3
  const char* lengthUnit() const { return inch ? "in" : "mm"; }
  const char* feedUnit() const { return inch ? "in/min" : "mm/min"; }
  const char* accelerationUnit() const { return inch ? "in/s^2" : "mm/s^2"; }
  const char* jerkUnit() const { return inch ? "in/s^3" : "mm/s^3"; }
  // A quantity's unit as the map shows it: its millimetre unit, or the inch one for a length
  // and its rates (a unit of something else, as um of deviation or s, stays).
  const char* unitOf(const char* mmUnit) const {
    if (!inch) return mmUnit;
    const std::string_view u(mmUnit);
    if (u == "mm") return "in";
    if (u == "mm/min") return feedUnit();
    if (u == "mm/s^2") return accelerationUnit();
    if (u == "mm/s^3") return jerkUnit();
    return mmUnit;
  }
  // What the three curves of motion (feed, acceleration, jerk) are read to, in their display
  // units: far below what a machine's figures are told apart by, far above differencing noise
  // (0.01 mm/min, 0.01 mm/s^2, 1 mm/s^3, and as much in inches: an inch acceleration read to
  // 0.01 in/s^2 showed 0.2 mm/s^2 as 0).
  double motionResolution(std::size_t curve) const { return length(curve < 2 ? 0.01 : 1.0); }
  // Decimals that show a length to about a micrometre.
  int lengthDecimals() const { return inch ? 5 : 4; }
};

}  // namespace isurface::panels
