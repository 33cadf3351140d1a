// Dividing cutting runs into passes for the three tool-path patterns of the paper's Figure 1.
#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <system_error>

#include "pass_split.h"

namespace isurface::passes_detail {

namespace {


bool finiteAt(const Trajectory& s, std::size_t i) {
  const double v = (s.x[i] - s.x[i]) + (s.y[i] - s.y[i]) + (s.z[i] - s.z[i]);
  return v == 0;
}

// Step from sample i to i + 1; false when either end is not finite.
bool step(const Trajectory& s, std::size_t i, double& dx, double& dy, double& dz) {
  dx = s.x[i + 1] - s.x[i];
  dy = s.y[i + 1] - s.y[i];
  dz = s.z[i + 1] - s.z[i];
  const double check = (dx - dx) + (dy - dy) + (dz - dz);
  return check == 0;
}

// Keeps the passes at least minimumPassLength long and adds them to `out`.
void keepLongEnough(const Trajectory& s, const Pass& pass, const PassOptions& options, std::vector<Pass>& out,
                    double* length = nullptr) {
  if (pass.end <= pass.begin + 1) return;
  const double l = pathLength(s, pass.begin, pass.end);
  if (length != nullptr) *length = l;
  if (l >= options.minimumPassLength) out.push_back(pass);
}

// --- direction-parallel -----------------------------------------------------------------------

// Sums of the steps' orientation tensor over samples [begin, end) of the runs: each step's unit
// direction times its length (xx, xy, yy).
struct OrientationSums {
  double xx = 0, xy = 0, yy = 0;
};

OrientationSums orientationSums(const Trajectory& s, const std::vector<Pass>& runs, std::size_t begin, std::size_t end) {
  OrientationSums sums;
  for (const Pass& run : runs) {
    const std::size_t last = std::min(run.end, end);
    for (std::size_t i = std::max(run.begin, begin); i + 1 < last; ++i) {
      double dx, dy, dz;
      if (!step(s, i, dx, dy, dz)) continue;
      const double l = std::sqrt(dx * dx + dy * dy);
      if (l <= kLengthEpsilon) continue;
      const double weight = 1.0 / l;  // one division, not three: they were a third of the split
      sums.xx += dx * dx * weight;
      sums.xy += dx * dy * weight;
      sums.yy += dy * dy * weight;
    }
  }
  return sums;
}

// Unit main direction of horizontal motion: the principal axis of the steps' orientation
// tensor, so that moves one way and back add up instead of cancelling. Above a million samples
// the second half of the steps is summed on a second thread; the halves depend only on the
// samples, so the axis is the same whether or not a second thread can be had.
void mainAxis(const Trajectory& s, const std::vector<Pass>& runs, double& ux, double& uy) {
  constexpr std::size_t kSideBySideSamples = 1'000'000;
  std::size_t size = 0;
  for (const Pass& run : runs) size = std::max(size, run.end);
  // The second half begins with the step from sample middle - 1 to middle.
  const std::size_t middle = size >= kSideBySideSamples ? size / 2 : size;
  std::future<OrientationSums> second;
  bool secondHere = middle < size;
  if (secondHere) {
    try {
      second = std::async(std::launch::async, [&] { return orientationSums(s, runs, middle - 1, size); });
      secondHere = false;
    } catch (const std::system_error&) {  // no thread to be had: both halves on this one
    }
  }
  OrientationSums sums = orientationSums(s, runs, 0, middle);
  if (middle < size) {
    const OrientationSums later = secondHere ? orientationSums(s, runs, middle - 1, size) : second.get();
    sums.xx += later.xx;
    sums.xy += later.xy;
    sums.yy += later.yy;
  }
  const double angle = 0.5 * std::atan2(2 * sums.xy, sums.xx - sums.yy);
  ux = std::cos(angle);
  uy = std::sin(angle);
}

struct Candidate {
  Pass pass;
  double length = 0;
};

}  // namespace

std::vector<Pass> splitDirectionParallel(const Trajectory& s, const std::vector<Pass>& runs,
                                         const PassOptions& options, PatternFit* fit) {
  // A straight pass keeps its XY chord within these of its XY path and of the main axis.
  constexpr double kStraightness = 0.9;
  const double parallelCos = std::cos(20.0 * kPi / 180.0);

  double ux, uy;
  mainAxis(s, runs, ux, uy);
  std::vector<Pass> out;
  for (const Pass& run : runs) {
    // Heading along the axis of each step: +1 or -1 within 45 degrees of it, 0 across it (a
    // step-over). Vertical steps and standstill keep the heading they are in.
    int heading = 0;
    std::size_t start = run.begin;
    double xyPath = 0;
    // mm: of the run, and of the pass since `start` up to the step before the current one, summed
    // in the order pathLength() sums them (one walk over the samples instead of three).
    double runLength = 0, passLength = 0;
    const auto close = [&](std::size_t end) {
      if (heading == 0) return;
      const Pass pass{start, std::max(end, start)};
      if (pass.end <= pass.begin + 1 || passLength < options.minimumPassLength) return;
      out.push_back(pass);
      if (fit == nullptr) return;
      // Fit: straight in XY and parallel to the axis.
      std::size_t a = pass.begin, b = pass.end - 1;
      while (a < b && !finiteAt(s, a)) ++a;
      while (b > a && !finiteAt(s, b)) --b;
      const double cx = s.x[b] - s.x[a], cy = s.y[b] - s.y[a];
      const double chord = std::sqrt(cx * cx + cy * cy);
      if (chord >= kStraightness * xyPath && std::fabs(cx * ux + cy * uy) >= parallelCos * chord) {
        fit->fittingLength += passLength;
        ++fit->fittingPasses;
      }
    };
    for (std::size_t i = run.begin; i + 1 < run.end; ++i) {
      double dx, dy, dz;
      if (!step(s, i, dx, dy, dz)) continue;
      const double along = dx * ux + dy * uy, across = -dx * uy + dy * ux;
      const double xy = std::sqrt(dx * dx + dy * dy);
      const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
      const bool finiteLength = length == length && length - length == 0;
      int now = heading;
      if (xy > kLengthEpsilon) now = std::fabs(along) >= std::fabs(across) ? (along > 0 ? 1 : -1) : 0;
      if (now != heading) {
        close(i + 1);
        heading = now;
        start = i;
        if (!out.empty() && out.back().end > start) start = out.back().end;
        xyPath = 0;
        passLength = 0;
      }
      xyPath += xy;
      if (finiteLength) {
        runLength += length;
        if (start <= i) passLength += length;
      }
    }
    close(run.end);
    if (fit != nullptr) fit->cuttingLength += runLength;
  }
  return out;
}

// --- contour-parallel -------------------------------------------------------------------------

namespace {

// Turning of the horizontal heading that closes a loop, and how far past it the end is sought.
constexpr double kTurnToSeek = 1.75 * kPi;
constexpr double kTurnLimit = 2.25 * kPi;
// mm of path, seen from above, before a loop's end that give its closing heading.
constexpr double kClosingStretch = 0.3;

struct Turn {
  std::size_t end = 0;     // the sample nearest the start after about one turn (exclusive end - 1)
  bool complete = false;   // a turn was completed
  double closingX = 0, closingY = 0;  // horizontal heading at the end
  double length = 0;       // mm of path of the turn
};

// Walks from `start` while the heading turns less than kTurnLimit and returns the sample
// nearest the start among those after kTurnToSeek of turning. When the step into that sample
// turns sharply (more than 45 degrees) it is the first step of the link to the next loop,
// which leaves from the loop's start: the loop ends at the corner before it instead.
Turn walkOneTurn(const Trajectory& s, std::size_t start, std::size_t runEnd) {
  const double sharpTurn = kPi / 4;
  Turn turn;
  turn.end = runEnd - 1;
  double turned = 0, length = 0, best = std::numeric_limits<double>::infinity();
  double hx = 0, hy = 0;  // last horizontal heading (unnormalised)
  double bestHx = 0, bestHy = 0, bestLength = 0;
  double cornerHx = 0, cornerHy = 0, cornerLength = 0;  // heading and length before a sharp last step
  bool sharpEnd = false;
  const double x0 = s.x[start], y0 = s.y[start], z0 = s.z[start];
  for (std::size_t i = start; i + 1 < runEnd; ++i) {
    double dx, dy, dz;
    if (!step(s, i, dx, dy, dz)) continue;
    const double before = length;
    const double beforeHx = hx, beforeHy = hy;
    length += std::sqrt(dx * dx + dy * dy + dz * dz);
    double stepTurn = 0;
    if (dx * dx + dy * dy > kLengthEpsilon * kLengthEpsilon) {
      if (hx != 0 || hy != 0) stepTurn = std::atan2(hx * dy - hy * dx, hx * dx + hy * dy);
      turned += stepTurn;
      hx = dx;
      hy = dy;
    }
    const double a = std::fabs(turned);
    if (a > kTurnLimit) break;
    if (a >= kTurnToSeek) {
      const double ex = s.x[i + 1] - x0, ey = s.y[i + 1] - y0, ez = s.z[i + 1] - z0;
      const double d = ex * ex + ey * ey + ez * ez;
      if (d < best) {
        best = d;
        turn.end = i + 1;
        turn.complete = true;
        bestHx = hx;
        bestHy = hy;
        bestLength = length;
        sharpEnd = std::fabs(stepTurn) > sharpTurn && i > start;
        cornerHx = beforeHx;
        cornerHy = beforeHy;
        cornerLength = before;
      }
    }
  }
  if (turn.complete && sharpEnd && (cornerHx != 0 || cornerHy != 0)) {
    turn.end -= 1;
    bestHx = cornerHx;
    bestHy = cornerHy;
    bestLength = cornerLength;
  }
  if (turn.complete) {
    // The loop's heading over its last stretch, not its last step's: where the control rounds
    // the corner into the link, the sample nearest the start may lie a few micrometres into the
    // link, heading its way.
    std::size_t from = turn.end;
    double back = 0;
    while (from > start && back < kClosingStretch) {
      --from;
      back = std::hypot(s.x[turn.end] - s.x[from], s.y[turn.end] - s.y[from]);
    }
    if (back >= kClosingStretch && std::isfinite(back)) {
      bestHx = s.x[turn.end] - s.x[from];
      bestHy = s.y[turn.end] - s.y[from];
    }
    const double h = std::sqrt(bestHx * bestHx + bestHy * bestHy);
    turn.closingX = bestHx / h;
    turn.closingY = bestHy / h;
    turn.length = bestLength;
  } else {
    turn.length = length;
  }
  return turn;
}

// After a loop closes at `from`, skips the link to the next loop: a stretch that leaves the
// closing heading (by more than 45 degrees, or going mostly vertical) soon after the closure
// and ends where the heading comes back to within 30 degrees of it, or of its opposite (the
// next loop may run the other way round). The sample after the link's last step starts the
// next loop. A spiral has no link.
std::size_t skipLink(const Trajectory& s, std::size_t from, std::size_t runEnd, const Turn& turn) {
  const double leaveCos = std::cos(kPi / 4), backCos = std::cos(kPi / 6);
  const double leaveWithin = std::min(2.0, 0.1 * turn.length);   // mm
  const double backWithin = std::min(10.0, 0.5 * turn.length);   // mm
  double length = 0;
  bool left = false;
  for (std::size_t i = from; i + 1 < runEnd; ++i) {
    double dx, dy, dz;
    if (!step(s, i, dx, dy, dz)) continue;
    const double xy = std::sqrt(dx * dx + dy * dy);
    const double l = std::sqrt(xy * xy + dz * dz);
    if (l > kLengthEpsilon) {
      const bool steep = std::fabs(dz) > xy;
      const double c = xy > kLengthEpsilon ? (dx * turn.closingX + dy * turn.closingY) / xy : 0;
      const bool parallel = !steep && std::fabs(c) >= backCos;
      // The heading has come back: the link's last step ended at this step's start, the loop's
      // first sample.
      if (left && parallel) return i;
      if (steep || c < leaveCos) left = true;
    }
    length += l;
    if (!left && length > leaveWithin) return from;
    if (length > backWithin) return from;
  }
  return from;
}

}  // namespace

std::vector<Pass> splitContourParallel(const Trajectory& s, const std::vector<Pass>& runs,
                                       const PassOptions& options, PatternFit* fit) {
  std::vector<Pass> out;
  for (const Pass& run : runs) {
    if (fit != nullptr) fit->cuttingLength += pathLength(s, run.begin, run.end);
    std::size_t start = run.begin;
    while (start + 1 < run.end) {
      if (!finiteAt(s, start)) {
        ++start;
        continue;
      }
      const Turn turn = walkOneTurn(s, start, run.end);
      if (!turn.complete) {
        keepLongEnough(s, {start, run.end}, options, out);
        break;
      }
      const std::size_t kept = out.size();
      double length = 0;
      keepLongEnough(s, {start, turn.end + 1}, options, out, &length);
      if (fit != nullptr && out.size() > kept) {
        fit->fittingLength += length;
        ++fit->fittingPasses;
      }
      start = std::max(turn.end + 1, skipLink(s, turn.end, run.end, turn));
    }
  }
  return out;
}

// --- no boundary ------------------------------------------------------------------------------

std::vector<Pass> splitNoBoundary(const Trajectory& s, const std::vector<Pass>& runs, const PassOptions& options) {
  const double every = options.noBoundaryDistance > 0 ? options.noBoundaryDistance : 50.0;
  std::vector<Pass> out;
  for (const Pass& run : runs) {
    const std::size_t first = out.size();
    std::size_t start = run.begin;
    double length = 0;
    for (std::size_t i = run.begin; i + 1 < run.end; ++i) {
      double dx, dy, dz;
      if (step(s, i, dx, dy, dz)) length += std::sqrt(dx * dx + dy * dy + dz * dz);
      if (length >= every) {
        out.push_back({start, i + 1});
        start = i + 1;
        length = 0;
      }
    }
    if (start + 1 >= run.end) continue;
    if (length >= options.minimumPassLength || out.size() == first) {
      keepLongEnough(s, {start, run.end}, options, out);
    } else {
      out.back().end = run.end;  // a short tail joins the piece before it
    }
  }
  return out;
}

}  // namespace isurface::passes_detail
