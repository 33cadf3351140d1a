#pragma once
// How long each G-code line runs and when it starts, from the samples' line channel: the G-code
// pane's time columns.
#include <cstdint>
#include <optional>
#include <vector>

#include "isurface/base/trajectory.h"

namespace isurface::app_model {

struct LineTime {
  std::uint32_t line = 0;
  double seconds = 0;  // s, all its samples (a line run twice, in a loop or a subprogram, adds up)
  double start = 0;    // s from the run's first sample, at its first sample
};

class LineTimes {
 public:
  LineTimes() = default;
  explicit LineTimes(const Trajectory& samples);

  // Nothing for a line without samples.
  std::optional<LineTime> of(std::uint32_t line) const;

 private:
  std::vector<LineTime> lines_;  // sorted by line
};

}  // namespace isurface::app_model
