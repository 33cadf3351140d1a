#pragma once
// The Locate window's model: go to a sample, a G-code line or the sample nearest a point, and
// say why a request went nowhere.
#include <cstddef>
#include <string>

#include "isurface/app_model/selection.h"
#include "isurface/base/geometry.h"

namespace isurface::app_model {

struct LocateWindow {
  bool opening = false;  // asked for: shown, at the front, from the next frame
  bool open = false;
  int sample = 0, line = 1;    // the fields: a sample index (0-based), a line (1-based)
  Vec3 point = Vec3::Zero();   // mm
  std::string message;         // why the last request went nowhere

  // Opens it at the selection: its sample, its line and the sample's position.
  void show(const SelectionModel& selection);
  // Each selects what its field names, or leaves the selection and says why. `lines`: the
  // program's line count (0: no program).
  void goToSample(SelectionModel& selection);
  void goToLine(SelectionModel& selection, std::size_t lines);
  // The sample nearest `point`, and how far it is (in the message) when it is not on it.
  void goToPoint(SelectionModel& selection);
};

}  // namespace isurface::app_model
