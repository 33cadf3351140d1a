#include "isurface/nc/feed_cap_notes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "isurface/base/units.h"
#include "isurface/gcode/path_segment.h"

namespace isurface {

namespace {

// Share above the axes' limit a feed may be without a note: a feed written as the limit itself
// rounds either way.
constexpr double kSlack = 0.001;

// mm/s: the fastest the axes allow along the move (on an arc, both plane axes reach its speed).
double axesLimit(const Machine& machine, const PathSegment& seg) {
  const auto& ax = machine.axes;
  double limit = std::numeric_limits<double>::infinity();
  if (seg.arc) {
    const ArcGeometry& g = seg.arcGeometry;
    limit = std::min(ax[g.axes.u].maxVelocity, ax[g.axes.v].maxVelocity);
    const double pitch = seg.length > 0 ? std::abs(g.endW - g.startW) / seg.length : 0;
    if (pitch > 0) limit = std::min(limit, ax[g.axes.w].maxVelocity / pitch);
    return limit;
  }
  for (int i = 0; i < 3; ++i)
    if (std::abs(seg.direction[i]) > 0) limit = std::min(limit, ax[i].maxVelocity / std::abs(seg.direction[i]));
  return limit;
}

}  // namespace

void FeedCapNotes::note(const Move& move, const Vec3& start) {
  if (move.kind == MoveKind::Rapid || move.kind == MoveKind::Dwell) return;
  const PathSegment seg = PathSegment::from(start, move);
  if (!(seg.length > 0)) return;
  const double limit = axesLimit(machine_, seg);
  if (!(mmPerMinToMmPerS(static_cast<double>(move.feed)) > limit * (1 + kSlack))) return;
  if (capped_++ == 0) {
    first_ = move;
    firstLimitMmMin_ = mmPerSToMmPerMin(limit);
  }
}

std::optional<Diagnostic> FeedCapNotes::warning(const std::string& source) const {
  if (capped_ == 0) return std::nullopt;
  std::string text = fmt::format("F{} is faster than the machine's axes allow along this move ({:.0f} mm/min): it runs at "
                                 "their limit",
                                 first_.feed, firstLimitMmMin_);
  if (capped_ > 1) text += fmt::format(", as {} more {}", capped_ - 1, capped_ > 2 ? "moves do" : "move does");
  return Diagnostic{source, first_.line, first_.column, text};
}

}  // namespace isurface
