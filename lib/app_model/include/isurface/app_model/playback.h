#pragma once
// Scrubbing and playing a run: the selection moved through the samples by their time, as a
// preview plays the tool along its path.
#include <cstddef>

#include "isurface/app_model/selection.h"

namespace isurface::app_model {

// The sample running at `seconds` from the run's first sample: the last one at or before it.
std::size_t sampleAtTime(const Trajectory& samples, double seconds);

struct Playback {
  bool playing = false;
  double speed = 1;  // seconds of the run per second of the clock

  // Starts from the selected sample (the first, or again from the first at the end), or pauses.
  void toggle(const SelectionModel& selection);
  // Moves the selection on by `clockSeconds` times the speed; stops at the run's last sample.
  void advance(SelectionModel& selection, double clockSeconds);

 private:
  double at_ = 0;  // s from the run's first sample
};

}  // namespace isurface::app_model
