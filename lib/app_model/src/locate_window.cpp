#include "isurface/app_model/locate_window.h"

#include <fmt/format.h>

#include <cmath>

namespace isurface::app_model {

namespace {
// A sample this close to the point asked for (mm) is on it: nothing to say.
constexpr double kOnPoint = 1e-3;
}  // namespace

void LocateWindow::show(const SelectionModel& selection) {
  const Selection& current = selection.current();
  if (current.sample) {
    sample = static_cast<int>(*current.sample);
    if (const Trajectory* t = selection.trajectory(); t && *current.sample < t->size())
      point = Vec3(t->x[*current.sample], t->y[*current.sample], t->z[*current.sample]);
  }
  if (current.line) line = static_cast<int>(*current.line);
  message.clear();
  opening = open = true;
}

void LocateWindow::goToSample(SelectionModel& selection) {
  message.clear();
  const Trajectory* t = selection.trajectory();
  const std::size_t samples = t ? t->size() : 0;
  if (samples == 0) message = "no samples: simulate or open a dump";
  else if (sample < 0 || static_cast<std::size_t>(sample) >= samples)
    message = fmt::format("sample {} is out of range: 0 .. {}", sample, samples - 1);
  else selection.selectSample(static_cast<std::size_t>(sample));
}

void LocateWindow::goToLine(SelectionModel& selection, std::size_t lines) {
  message.clear();
  if (lines == 0) message = "no program";
  else if (line < 1 || static_cast<std::size_t>(line) > lines)
    message = fmt::format("line {} is out of range: 1 .. {}", line, lines);
  else if (!selection.selectLine(static_cast<std::uint32_t>(line)))
    message = fmt::format("line {} produced no samples", line);
}

void LocateWindow::goToPoint(SelectionModel& selection) {
  message.clear();
  if (!point.allFinite()) {
    message = "the point must have finite X, Y and Z";
    return;
  }
  if (!selection.selectNearest(point)) {
    message = "no samples with a position: simulate or open a dump";
    return;
  }
  const Trajectory& t = *selection.trajectory();
  const std::size_t i = *selection.current().sample;
  const double distance = (Vec3(t.x[i], t.y[i], t.z[i]) - point).norm();
  if (distance > kOnPoint) message = fmt::format("the nearest sample, {}, is {:.4g} mm from the point", i, distance);
}

}  // namespace isurface::app_model
