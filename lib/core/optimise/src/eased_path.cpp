#include "isurface/optimise/eased_path.h"

#include <algorithm>
#include <cmath>

#include "isurface/base/tolerances.h"
#include "isurface/optimise/polyline_distance.h"

namespace isurface {

namespace {

constexpr double kSpacing = 0.01;      // mm between the points the path is averaged over
constexpr double kWidestWindow = 4.0;  // mm; a wider one only reaches further along straights
// Where a bend runs slower than the feed, it is written in pieces of at most kBendPiece (mm): a
// ramp into or out of it changes the feed from one piece to the next (feed_ramps.h), and over
// longer pieces (yet too short for the ramp to cut) it would change in coarser steps, which the
// NC follows late when speeding up and early when slowing down, so that a pass and its
// neighbour cut the other way would disagree.
constexpr double kBendPiece = 0.05;
// The new segments searched beyond the one found nearest the last (after walking forward while
// the next is no farther): the eased path leaves the program's by micrometres, so the nearest
// old segment is among the next few once the walk stops.
constexpr std::size_t kLookAhead = 16;

// The polyline at every kSpacing of its length, its last point kept.
std::vector<Vec3> resampled(const std::vector<Vec3>& path) {
  std::vector<Vec3> out = {path.front()};
  double carried = 0;  // mm walked since the last point written
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const Vec3 step = path[k + 1] - path[k];
    const double length = step.norm();
    if (!(length > kLengthEpsilon)) continue;
    double at = kSpacing - carried;
    for (; at <= length; at += kSpacing) out.push_back(path[k] + step * (at / length));
    carried = length - (at - kSpacing);
  }
  if ((out.back() - path.back()).norm() > kLengthEpsilon) out.push_back(path.back());
  return out;
}

// Each point the mean of the 2 * half + 1 points around it (half < size), the path mirrored
// through its end points beyond them: each end stays where it is (the unchanged lines before
// and after the pass join it there) and the curvature tapers to nothing at it, a straight end
// staying straight.
std::vector<Vec3> averaged(const std::vector<Vec3>& path, std::size_t half) {
  const std::ptrdiff_t n = std::ptrdiff_t(path.size()), h = std::ptrdiff_t(half);
  auto at = [&](std::ptrdiff_t i) -> Vec3 {
    if (i < 0) return 2 * path.front() - path[std::size_t(-i)];
    if (i >= n) return 2 * path.back() - path[std::size_t(2 * (n - 1) - i)];
    return path[std::size_t(i)];
  };
  Vec3 sum = Vec3::Zero();
  for (std::ptrdiff_t i = -h; i <= h; ++i) sum += at(i);
  std::vector<Vec3> out(path.size());
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    out[std::size_t(k)] = sum / double(2 * h + 1);
    if (k + 1 < n) sum += at(k + h + 1) - at(k - h);
  }
  out.front() = path.front();  // only rounding moved them
  out.back() = path.back();
  return out;
}

// The dense path as chords: a point is written before the turn since the last one would pass
// `maxTurn`, the chord would stray more than `chordTolerance` from the curvature met, or a
// piece of a bend sharper than `bendCurvature` (1/mm) would be longer than kBendPiece.
std::vector<Vec3> chords(const std::vector<Vec3>& dense, double chordTolerance, double maxTurn, double bendCurvature) {
  std::vector<Vec3> out = {dense.front()};
  double turn = 0, length = 0, curvature = 0;
  for (std::size_t j = 1; j + 1 < dense.size(); ++j) {
    const Vec3 in = dense[j] - dense[j - 1], next = dense[j + 1] - dense[j];
    const double a = in.norm(), b = next.norm();
    length += a;
    double t = 0;
    if (a > kLengthEpsilon && b > kLengthEpsilon) t = std::acos(std::clamp(in.dot(next) / (a * b), -1.0, 1.0));
    const double bent = std::max(curvature, t / std::max(a, b));
    const double longest = bent > kZeroCurvature ? std::sqrt(8.0 * chordTolerance / bent) : INFINITY;
    if (turn + t > maxTurn || length + b > longest || (bent > bendCurvature && length + b > kBendPiece)) {
      out.push_back(dense[j]);
      turn = length = curvature = 0;
      continue;
    }
    turn += t;
    curvature = bent;
  }
  // A last chord shorter than the spacing (the resampled path's last step) joins the one before.
  if (out.size() > 1 && (dense.back() - out.back()).norm() < 0.5 * kSpacing) out.pop_back();
  out.push_back(dense.back());
  return out;
}

// Per segment of `path`, the segment of `program` nearest its middle, searched forward: the
// paths run the same way.
std::vector<std::size_t> besideSegments(const std::vector<Vec3>& path, const std::vector<Vec3>& program) {
  std::vector<std::size_t> beside;
  if (program.size() < 2) return std::vector<std::size_t>(path.size() > 0 ? path.size() - 1 : 0, 0);
  const std::size_t segments = program.size() - 1;
  std::size_t j = 0;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const Vec3 middle = 0.5 * (path[k] + path[k + 1]);
    auto distance = [&](std::size_t i) { return distanceToSegment(middle, program[i], program[i + 1]); };
    while (j + 1 < segments && distance(j + 1) <= distance(j)) ++j;
    std::size_t best = j;
    for (std::size_t i = j + 1; i < segments && i <= j + kLookAhead; ++i)
      if (distance(i) < distance(best)) best = i;
    beside.push_back(j = best);
  }
  return beside;
}

}  // namespace

EasedPath easedPath(const std::vector<Vec3>& smooth, const std::vector<Vec3>& program, const EasingLimits& limits) {
  EasedPath eased{smooth, {}, 0};
  if (smooth.size() >= 3 && program.size() >= 2 && limits.tube > 0) {
    const std::vector<Vec3> dense = resampled(smooth);
    if (dense.size() >= 3) {
      // The widest window within the tube: the path moves further from the program's the wider
      // it is averaged, so the search halves the range of half-widths.
      std::size_t lo = 0, hi = std::min((dense.size() - 1) / 2, std::size_t(kWidestWindow / kSpacing / 2));
      std::vector<Vec3> best;
      while (lo < hi) {
        const std::size_t half = (lo + hi + 1) / 2;
        std::vector<Vec3> candidate =
            chords(averaged(averaged(dense, half), half), limits.chordTolerance, limits.maxTurn, limits.bendCurvature);
        if (polylineDistance(candidate, program) <= limits.tube) {
          lo = half;
          best = std::move(candidate);
        } else {
          hi = half - 1;
        }
      }
      if (lo > 0) eased = {std::move(best), {}, double(2 * lo + 1) * kSpacing};
    }
  }
  eased.oldSegment = besideSegments(eased.points, program);
  return eased;
}

}  // namespace isurface
