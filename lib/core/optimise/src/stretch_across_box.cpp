#include "isurface/optimise/stretch_across_box.h"

#include <algorithm>
#include <iterator>
#include <limits>

#include "isurface/base/tolerances.h"

namespace isurface {

namespace {

// mm: a move this long is a straight where a re-planned stretch of a pass may meet the old one:
// the widest window a bend is eased over fits on it. Shorter ones (a bend's chords, which a
// chord tolerance makes a few mm long where a blend flattens out) are re-planned with their bend.
constexpr double kPlanStraight = 4.0;
// mm: how far beyond the box's stretch along a pass it is re-planned:
// half the widest window an eased bend is averaged over, so that a bend the box cuts is eased
// as a whole.
constexpr double kPlanStretchMargin = 2.0;

}  // namespace

std::vector<std::size_t> stretchAcrossBox(const Program& program, const std::vector<std::size_t>& run,
                                          const std::pair<Vec3, Vec3>& box) {
  if (run.empty()) return run;
  Vec3 along = program.moves[run.back()].end - program.startOf(run.front());
  along.z() = 0;
  if (!(along.norm() > kLengthEpsilon)) return run;
  along.normalize();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const double x : {box.first.x(), box.second.x()})
    for (const double y : {box.first.y(), box.second.y()}) {
      const double s = x * along.x() + y * along.y();
      lo = std::min(lo, s), hi = std::max(hi, s);
    }
  lo -= kPlanStretchMargin, hi += kPlanStretchMargin;
  auto reaches = [&](std::size_t i) {
    const double a = program.startOf(i).dot(along), b = program.moves[i].end.dot(along);
    return std::max(a, b) >= lo && std::min(a, b) <= hi;
  };
  auto length = [&](std::size_t i) { return (program.moves[i].end - program.startOf(i)).norm(); };
  auto first = std::find_if(run.begin(), run.end(), reaches);
  if (first == run.end()) return {};
  auto last = std::prev(std::find_if(run.rbegin(), run.rend(), reaches).base());
  while (first != run.begin() && length(*first) < kPlanStraight) --first;
  while (std::next(last) != run.end() && length(*last) < kPlanStraight) ++last;
  return std::vector<std::size_t>(first, std::next(last));
}

}  // namespace isurface
