#include "isurface/optimise/feed_ramps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "isurface/base/tolerances.h"
#include "isurface/base/units.h"

namespace isurface {

namespace {

constexpr double kShortestRampPiece = 0.05;  // mm: finer pieces only multiply lines
constexpr double kShortestBendMove = 1e-3;   // mm: a turn beside a shorter move is rounding
constexpr double kFeedStepShare = 0.01;      // of the programmed feed, from a ramp's move to the next
constexpr double kLowestFeedShare = 0.2;     // of the programmed feed, no bend runs slower

// The feed each move may run at before ramping: its interval's (mm/min).
std::vector<double> intervalFeedPerMove(const PassFeeds& pass, double programmedFeed) {
  std::vector<double> feeds;
  std::size_t interval = 0;
  for (std::size_t k = 1; k < pass.points.size(); ++k) {
    while (interval + 1 < pass.intervalEnd.size() && k > pass.intervalEnd[interval]) ++interval;
    feeds.push_back(pass.feeds.empty() ? programmedFeed : pass.feeds[std::min(interval, pass.feeds.size() - 1)]);
  }
  return feeds;
}

// The path's curvature at each point (1/mm): one over the radius of the circle through it and
// its neighbours (equation 1 of the paper); 0 at the ends and beside a move under a micrometre.
// (The junction of a long straight move and a bend has little: the bend's feed is set by its
// own short moves.)
std::vector<double> curvatureAtPoints(const std::vector<Vec3>& points) {
  std::vector<double> curvature(points.size(), 0.0);
  for (std::size_t k = 1; k + 1 < points.size(); ++k) {
    if ((points[k] - points[k - 1]).norm() < kShortestBendMove || (points[k + 1] - points[k]).norm() < kShortestBendMove)
      continue;
    curvature[k] = 1.0 / threePointRadius(points[k - 1], points[k], points[k + 1]);
  }
  return curvature;
}

// Per point, the speed the bound allows where the path bends by `curvature` (1/mm): mm/s,
// infinite on a straight, never below `lowest`.
std::vector<double> boundAtPoints(const std::vector<double>& curvature, double limit, double lowest) {
  std::vector<double> atPoint(curvature.size(), std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < curvature.size(); ++k)
    if (curvature[k] > kZeroCurvature) atPoint[k] = std::max(lowest, std::sqrt(limit / curvature[k]));
  return atPoint;
}

// The ramp's speed at every point (mm/s): no more than the feeds of the moves it joins, and
// reachable from its neighbours at each move's ramp acceleration `a` (mm/s^2), both ways along
// the pass.
std::vector<double> speedAtPoints(const std::vector<Vec3>& points, const std::vector<double>& feeds, const std::vector<double>& a,
                                  const std::vector<double>& atPoint) {
  const std::size_t n = points.size();
  std::vector<double> u(n);
  for (std::size_t k = 0; k < n; ++k) u[k] = std::min(feeds[k > 0 ? k - 1 : 0], feeds[std::min(k, feeds.size() - 1)]);
  for (std::size_t k = 0; k < n && k < atPoint.size(); ++k) u[k] = std::min(u[k], atPoint[k]);
  for (std::size_t k = 0; k + 1 < n; ++k)
    u[k + 1] = std::min(u[k + 1], std::sqrt(u[k] * u[k] + 2 * a[k] * (points[k + 1] - points[k]).norm()));
  for (std::size_t k = n - 1; k > 0; --k)
    u[k - 1] = std::min(u[k - 1], std::sqrt(u[k] * u[k] + 2 * a[k - 1] * (points[k] - points[k - 1]).norm()));
  return u;
}

// Distances along one move (0..length, mm) where the ramp's speed crosses a whole multiple of
// the step: rising from its start, falling towards its end.
std::vector<double> rampBreaks(double length, double feed, double atStart, double atEnd, double a, double step) {
  // Where the ramp reaches the move's feed a break must stay: the rest of the move holds the
  // feed (dropped, the long piece beyond would run at the step below, and a feed between two
  // steps always would).
  struct Break {
    double s;
    bool reachesFeed;
  };
  std::vector<Break> breaks;
  for (const auto& [from, mirrored] : {std::pair{atStart, false}, std::pair{atEnd, true}}) {
    if (!(from < feed)) continue;
    for (double level = (std::floor(from / step) + 1) * step;; level += step) {
      const bool top = level >= feed * (1 - 1e-9);
      const double reached = top ? feed : level;
      const double s = (reached * reached - from * from) / (2 * a);
      if (s >= length) break;
      breaks.push_back({mirrored ? length - s : s, top});
      if (top) break;
    }
  }
  // A break nearer an end than the shortest piece moves away from it rather than being left
  // out: left out, the whole long move before it would run at the step below.
  if (length < 2 * kShortestRampPiece) return {};
  for (Break& b : breaks) b.s = std::clamp(b.s, kShortestRampPiece, length - kShortestRampPiece);
  std::sort(breaks.begin(), breaks.end(), [](const Break& x, const Break& y) { return x.s < y.s; });
  std::vector<Break> kept;
  for (const Break& b : breaks) {
    if (kept.empty() || b.s - kept.back().s >= kShortestRampPiece) kept.push_back(b);
    else if (b.reachesFeed && !kept.back().reachesFeed) kept.back() = b;
  }
  std::vector<double> at;
  for (const Break& b : kept) at.push_back(b.s);
  return at;
}

// Whether the segment from `a` to `b`, seen from above, meets the box (its XY, sides included;
// clipped to it as Liang and Barsky do).
bool reachesInto(const Vec3& a, const Vec3& b, const std::pair<Vec3, Vec3>& box) {
  double enter = 0, leave = 1;
  for (int axis = 0; axis < 2; ++axis) {
    const double d = b[axis] - a[axis], lower = box.first[axis] - kOnBoxSide, upper = box.second[axis] + kOnBoxSide;
    if (std::fabs(d) < kLengthEpsilon) {
      if (a[axis] < lower || a[axis] > upper) return false;
      continue;
    }
    double t0 = (lower - a[axis]) / d, t1 = (upper - a[axis]) / d;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return false;
  }
  return true;
}

// A pass as the ramps see it. Per point: the speed the bends' bound allows there and a cap
// (mm/s, infinite: none); per move: its interval's feed (mm/min), the bound it is held to over
// its length (mm/s), its ramps' acceleration (mm/s^2) and the old line it stands for.
struct RampPlan {
  std::vector<Vec3> points;
  std::vector<double> bound, cap;
  std::vector<double> intervalFeed, moveBound, acceleration;
  std::vector<std::uint32_t> line;
};

bool rampsAsked(const RampOptions& options, double programmed) {
  return programmed > 0 && std::isfinite(options.rampAcceleration) && options.rampAcceleration > 0;
}

RampPlan rampPlan(const PassFeeds& pass, const RampOptions& options, double programmed) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  RampPlan plan;
  plan.points = pass.points;
  plan.bound.assign(pass.points.size(), kNone);
  if (programmed > 0 && std::isfinite(options.normalAccelerationLimit) && options.normalAccelerationLimit > 0)
    plan.bound = boundAtPoints(curvatureAtPoints(pass.points), options.normalAccelerationLimit,
                               mmPerMinToMmPerS(kLowestFeedShare * programmed));
  plan.cap.assign(pass.points.size(), kNone);
  plan.intervalFeed = intervalFeedPerMove(pass, programmed);
  const bool ramped = rampsAsked(options, programmed);
  const double a = ramped ? options.rampAcceleration : 0.0;
  for (std::size_t k = 0; k + 1 < pass.points.size(); ++k) {
    // With ramps a move is held to the faster of its ends, the ramp from the slower end covering
    // the rest (a bend easing out over a long chord lets the speed rise from where it begins);
    // without, to the slower.
    plan.moveBound.push_back(ramped ? std::max(plan.bound[k], plan.bound[k + 1]) : std::min(plan.bound[k], plan.bound[k + 1]));
    // On a move that does not reach into the box asked for, the faster of the two accelerations.
    const bool outside = options.within && !reachesInto(pass.points[k], pass.points[k + 1], *options.within);
    plan.acceleration.push_back(outside ? std::max(a, options.outsideAcceleration) : a);
    plan.line.push_back(k + 1 < pass.sourceLines.size() ? pass.sourceLines[k + 1] : 0);
  }
  return plan;
}

FeedPerMove rampedFeeds(const RampPlan& plan, const RampOptions& options, double programmed) {
  FeedPerMove out;
  if (plan.points.empty()) return out;
  out.points = {plan.points.front()};
  out.sourceLines = {0};
  out.passPointAt = {0};
  // mm/s, each move's before ramping: its interval's, its bound, and the higher of its caps.
  std::vector<double> feeds;
  for (std::size_t k = 0; k < plan.intervalFeed.size(); ++k)
    feeds.push_back(std::min({mmPerMinToMmPerS(plan.intervalFeed[k]), plan.moveBound[k], std::max(plan.cap[k], plan.cap[k + 1])}));
  if (feeds.empty()) return out;
  std::vector<double> atPoint(plan.points.size());
  for (std::size_t k = 0; k < atPoint.size(); ++k) atPoint[k] = std::min(plan.bound[k], plan.cap[k]);
  // Ramps need a step to cut them at: none without a programmed feed.
  const bool ramped = rampsAsked(options, programmed);
  const double step = mmPerMinToMmPerS(kFeedStepShare * programmed);
  const std::vector<double> u = ramped ? speedAtPoints(plan.points, feeds, plan.acceleration, atPoint) : std::vector<double>{};
  for (std::size_t k = 0; k < feeds.size(); ++k) {
    const Vec3 &from = plan.points[k], &to = plan.points[k + 1];
    const double intervalFeed = plan.intervalFeed[k];
    if (!ramped) {
      out.points.push_back(to), out.sourceLines.push_back(plan.line[k]), out.feeds.push_back(std::min(intervalFeed, mmPerSToMmPerMin(feeds[k])));
      out.passPointAt.push_back(out.points.size() - 1);
      continue;
    }
    const double length = (to - from).norm();
    // The speeds the ramps hold at the move's ends, and their acceleration on it.
    const double atStart = u[k], atEnd = u[k + 1], a = plan.acceleration[k];
    // The ramp's speed at a distance s into the move; the lowest over a piece is at one of its ends.
    auto envelope = [&](double s) {
      return std::min({feeds[k], std::sqrt(atStart * atStart + 2 * a * s), std::sqrt(atEnd * atEnd + 2 * a * (length - s))});
    };
    // Cut from the same end whichever way the pass runs: a move run back the other way (the
    // next pass of a zig-zag) then ramps through the same pieces at the same feeds.
    const bool backwards = runsBackwards(from, to);
    std::vector<double> cuts = rampBreaks(length, feeds[k], backwards ? atEnd : atStart, backwards ? atStart : atEnd, a, step);
    if (backwards) {
      for (double& cut : cuts) cut = length - cut;
      std::reverse(cuts.begin(), cuts.end());
    }
    cuts.push_back(length);
    double s0 = 0;
    for (const double s1 : cuts) {
      const double lowest = std::min(envelope(s0), envelope(s1));
      // A piece of a ramp runs at the step below it; one that holds its move's feed keeps it.
      const double feed = lowest < feeds[k] * (1 - 1e-9) ? std::max(step, std::floor(lowest / step + 1e-9) * step) : feeds[k];
      out.points.push_back(s1 < length ? from + (to - from) * (s1 / length) : to);
      out.sourceLines.push_back(plan.line[k]);
      // Back in mm/min no faster than the interval's feed, not even by the rounding of the units.
      out.feeds.push_back(std::min(intervalFeed, mmPerSToMmPerMin(std::min(feed, feeds[k]))));
      s0 = s1;
    }
    out.passPointAt.push_back(out.points.size() - 1);
  }
  return out;
}

double programmedFeedOf(const RampOptions& options) {
  return std::isfinite(options.programmedFeed) && options.programmedFeed > 0 ? options.programmedFeed : 0.0;
}

}  // namespace

FeedPerMove feedPerMove(const PassFeeds& pass, const RampOptions& options) {
  const double programmed = programmedFeedOf(options);
  return rampedFeeds(rampPlan(pass, options, programmed), options, programmed);
}

FeedPerMove feedPerMoveHeldTo(const PassFeeds& pass, const FeedPerMove& ramped, const std::vector<double>& caps, const RampOptions& options) {
  const double programmed = programmedFeedOf(options);
  const RampPlan plan = rampPlan(pass, options, programmed);
  if (ramped.passPointAt.size() != pass.points.size() || caps.size() != ramped.points.size()) return rampedFeeds(plan, options, programmed);
  // Every point of the ramps a point of its own: a piece of a move keeps the move's feed, bound,
  // acceleration and line; the pass's own points keep their bound, the cuts (on a chord) none.
  RampPlan held;
  held.points = ramped.points;
  held.bound.assign(ramped.points.size(), std::numeric_limits<double>::infinity());
  for (std::size_t j = 0; j < pass.points.size(); ++j) held.bound[ramped.passPointAt[j]] = plan.bound[j];
  for (const double cap : caps) held.cap.push_back(mmPerMinToMmPerS(cap));
  for (std::size_t j = 0; j + 1 < pass.points.size(); ++j)
    for (std::size_t i = ramped.passPointAt[j]; i < ramped.passPointAt[j + 1]; ++i) {
      held.intervalFeed.push_back(plan.intervalFeed[j]);
      held.moveBound.push_back(plan.moveBound[j]);
      held.acceleration.push_back(plan.acceleration[j]);
      held.line.push_back(plan.line[j]);
    }
  FeedPerMove out = rampedFeeds(held, options, programmed);
  // Its points stand for the pass's where the pass's own points are.
  std::vector<std::size_t> at;
  for (const std::size_t i : ramped.passPointAt) at.push_back(out.passPointAt[i]);
  out.passPointAt = std::move(at);
  return out;
}

}  // namespace isurface
