#include "isurface/optimise/eased_path.h"

#include <algorithm>
#include <cmath>

#include "isurface/base/tolerances.h"
#include "isurface/optimise/polyline_distance.h"

namespace isurface {

namespace {

constexpr double kSpacing = 0.01;      // mm between the points the path is averaged over
constexpr double kWidestWindow = 4.0;  // mm; a wider one only reaches further along straights
// A bend (curvature above kBendCurvature, 1/mm) is written in pieces of at most kBendPiece (mm):
// a ramp into or out of it changes the feed from one piece to the next (feed_ramps.h), and over
// longer pieces it would change in coarser steps, which the NC follows late when speeding up and
// early when slowing down, so that a pass and its neighbour cut the other way would disagree.
constexpr double kBendCurvature = 1e-3;
constexpr double kBendPiece = 0.05;

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

// Each point the mean of the 2 * half + 1 points around it, the path extended straight beyond
// its ends (a straight end stays where it is).
std::vector<Vec3> averaged(const std::vector<Vec3>& path, std::size_t half) {
  const std::size_t n = path.size();
  // One spacing a step (the last step of the resampled path may be shorter).
  const Vec3 before = (path[0] - path[1]).normalized() * kSpacing, after = (path[n - 1] - path[n - 2]).normalized() * kSpacing;
  auto at = [&](std::ptrdiff_t i) -> Vec3 {
    if (i < 0) return path[0] + before * double(-i);
    if (i >= std::ptrdiff_t(n)) return path[n - 1] + after * double(i - std::ptrdiff_t(n) + 1);
    return path[std::size_t(i)];
  };
  const std::ptrdiff_t h = std::ptrdiff_t(half);
  Vec3 sum = Vec3::Zero();
  for (std::ptrdiff_t i = -h; i <= h; ++i) sum += at(i);
  std::vector<Vec3> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    out[k] = sum / double(2 * half + 1);
    sum += at(std::ptrdiff_t(k) + h + 1) - at(std::ptrdiff_t(k) - h);
  }
  out.front() = path.front();
  out.back() = path.back();
  return out;
}

// The dense path as chords: a point is written where the turn since the last one would pass
// `maxTurn`, the chord would stray more than `chordTolerance` from the curvature met, or a
// piece of a bend would be longer than kBendPiece.
std::vector<Vec3> chords(const std::vector<Vec3>& dense, double chordTolerance, double maxTurn) {
  std::vector<Vec3> out = {dense.front()};
  double turn = 0, length = 0, curvature = 0;
  for (std::size_t j = 1; j + 1 < dense.size(); ++j) {
    const Vec3 in = dense[j] - dense[j - 1], out_ = dense[j + 1] - dense[j];
    const double a = in.norm(), b = out_.norm();
    length += a;
    if (a > kLengthEpsilon && b > kLengthEpsilon) {
      const double t = std::acos(std::clamp(in.dot(out_) / (a * b), -1.0, 1.0));
      turn += t;
      curvature = std::max(curvature, t / std::max(a, b));
    }
    const double longest = curvature > kZeroCurvature ? std::sqrt(8.0 * chordTolerance / curvature) : INFINITY;
    if (turn >= maxTurn || length + b > longest || (curvature > kBendCurvature && length + b > kBendPiece)) {
      out.push_back(dense[j]);
      turn = length = curvature = 0;
    }
  }
  out.push_back(dense.back());
  return out;
}

// Per segment of `path`, the segment of `program` nearest its middle, searched forward.
std::vector<std::size_t> besideSegments(const std::vector<Vec3>& path, const std::vector<Vec3>& program) {
  constexpr std::size_t kLookAhead = 16;
  std::vector<std::size_t> beside;
  std::size_t j = 0;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const Vec3 middle = 0.5 * (path[k] + path[k + 1]);
    std::size_t best = j;
    double nearest = INFINITY;
    for (std::size_t i = j; i + 1 < program.size() && i < j + kLookAhead; ++i) {
      const double d = distanceToSegment(middle, program[i], program[i + 1]);
      if (d < nearest) nearest = d, best = i;
    }
    beside.push_back(j = best);
  }
  return beside;
}

}  // namespace

EasedPath easedPath(const std::vector<Vec3>& smooth, const std::vector<Vec3>& program, double tube,
                    double chordTolerance, double maxTurn) {
  EasedPath eased{smooth, {}, 0};
  if (smooth.size() >= 3 && program.size() >= 2 && tube > 0) {
    const std::vector<Vec3> dense = resampled(smooth);
    if (dense.size() >= 3) {
      // The widest window within the tube: the path moves further from the program's the wider
      // it is averaged, so the search halves the range of half-widths.
      std::size_t lo = 0, hi = std::min(dense.size() / 2, std::size_t(kWidestWindow / kSpacing / 2));
      std::vector<Vec3> best;
      while (lo < hi) {
        const std::size_t half = (lo + hi + 1) / 2;
        std::vector<Vec3> candidate = chords(averaged(averaged(dense, half), half), chordTolerance, maxTurn);
        if (polylineDistance(candidate, program) <= tube) {
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
