// Interpolation samples in memory, one array per channel.
#include "isurface/base/trajectory.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace isurface {

const std::vector<double>* Trajectory::extraChannel(const std::string& name) const {
  for (const auto& [channelName, values] : extra)
    if (channelName == name) return &values;
  return nullptr;
}

void Trajectory::attachFeedback(FeedbackOffsets&& offsets) {
  if (offsets.x.size() != size() || offsets.y.size() != size() || offsets.z.size() != size())
    throw std::invalid_argument("feedback offsets for " + std::to_string(offsets.size()) + " samples given to " +
                                std::to_string(size()) + " samples");
  fbOffsetX = std::move(offsets.x);
  fbOffsetY = std::move(offsets.y);
  fbOffsetZ = std::move(offsets.z);
}

bool timeIsIrregular(const double* time, std::size_t n, double cycle) {
  if (time == nullptr || n < 2) return false;
  const double tolerance = 1e-3 * cycle;
  for (std::size_t i = 1; i < n; ++i) {
    const double gap = time[i] - time[i - 1];
    // A non-finite time is irregular too (the comparison is false for NaN).
    if (!(std::fabs(gap - cycle) <= tolerance)) return true;
  }
  return false;
}

double machiningTime(const Trajectory& samples) {
  if (samples.size() < 2 || (!samples.time.empty() && samples.time.size() != samples.size())) return 0;
  const double span = samples.timeAt(samples.size() - 1) - samples.timeAt(0);
  return std::isfinite(span) && span > 0 ? span : 0;
}

}  // namespace isurface
