#include "isurface/app_model/playback.h"

#include <algorithm>
#include <cmath>

namespace isurface::app_model {

std::size_t sampleAtTime(const Trajectory& samples, double seconds) {
  const std::size_t n = samples.size();
  if (n == 0) return 0;
  const double t = samples.timeAt(0) + std::max(0.0, seconds);
  if (samples.time.empty()) {
    const double index = std::floor((t - samples.timeAt(0)) / samples.cycle + 1e-9);
    return static_cast<std::size_t>(std::clamp(index, 0.0, double(n - 1)));
  }
  const auto after = std::upper_bound(samples.time.begin(), samples.time.end(), t);
  return after == samples.time.begin() ? 0 : static_cast<std::size_t>(after - samples.time.begin()) - 1;
}

void Playback::toggle(const SelectionModel& selection) {
  if (playing) {
    playing = false;
    return;
  }
  const Trajectory* samples = selection.trajectory();
  if (!samples || samples->size() < 2) return;
  const std::size_t last = samples->size() - 1;
  const auto& selected = selection.current().sample;
  const std::size_t from = selected && *selected < last ? *selected : 0;
  at_ = samples->timeAt(from) - samples->timeAt(0);
  playing = true;
}

void Playback::advance(SelectionModel& selection, double clockSeconds) {
  const Trajectory* samples = selection.trajectory();
  if (!playing || !samples || samples->size() == 0) {
    playing = false;
    return;
  }
  at_ += std::max(0.0, clockSeconds) * speed;
  const std::size_t i = sampleAtTime(*samples, at_);
  if (!selection.current().sample || *selection.current().sample != i) selection.selectSample(i);
  if (i + 1 >= samples->size()) playing = false;
}

}  // namespace isurface::app_model
