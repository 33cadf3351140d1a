#pragma once
// Lengths, feeds and their derivatives as the window shows them: millimetres, or inches for a
// program written in inches (or when the user says so). Everything is computed in mm and s.
#include "isurface/base/units.h"

namespace isurface::panels {

struct DisplayUnits {
  bool inch = false;

  double length(double mm) const { return inch ? mm / kMmPerInch : mm; }  // also per s, s^2, s^3
  const char* lengthUnit() const { return inch ? "in" : "mm"; }
  const char* feedUnit() const { return inch ? "in/min" : "mm/min"; }
  const char* accelerationUnit() const { return inch ? "in/s^2" : "mm/s^2"; }
  const char* jerkUnit() const { return inch ? "in/s^3" : "mm/s^3"; }
  // Decimals that show a length to about a micrometre.
  int lengthDecimals() const { return inch ? 5 : 4; }
};

}  // namespace isurface::panels
