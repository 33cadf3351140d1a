#include "isurface/app_model/line_times.h"

#include <algorithm>

namespace isurface::app_model {

LineTimes::LineTimes(const Trajectory& samples) {
  const std::size_t n = samples.size();
  if (n == 0 || !samples.hasLine) return;
  const double origin = samples.timeAt(0);
  // A sample stands for the time until the next one; the last, for one cycle.
  const auto endOf = [&](std::size_t end) { return end < n ? samples.timeAt(end) : samples.timeAt(n - 1) + samples.cycle; };
  std::vector<LineTime> runs;
  samples.line.forEachRun([&](std::uint32_t line, std::size_t begin, std::size_t end) {
    if (line != 0) runs.push_back({line, endOf(end) - samples.timeAt(begin), samples.timeAt(begin) - origin});
  });
  // Stable: a line's first run stays first, and gives its start.
  std::stable_sort(runs.begin(), runs.end(), [](const LineTime& a, const LineTime& b) { return a.line < b.line; });
  for (const LineTime& r : runs) {
    if (!lines_.empty() && lines_.back().line == r.line) lines_.back().seconds += r.seconds;
    else lines_.push_back(r);
  }
  lines_.shrink_to_fit();
}

std::optional<LineTime> LineTimes::of(std::uint32_t line) const {
  const auto it = std::lower_bound(lines_.begin(), lines_.end(), line,
                                   [](const LineTime& t, std::uint32_t l) { return t.line < l; });
  if (it == lines_.end() || it->line != line) return std::nullopt;
  return *it;
}

}  // namespace isurface::app_model
