// The paper's steps pass by pass: each pass's points fitted interval by interval (or drawn anew
// in the shape asked for) and one feed planned per constant speed interval.
#include "pass_plans.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <future>
#include <limits>
#include <numeric>

#include "isurface/base/geometry.h"
#include "isurface/base/tolerances.h"
#include "isurface/base/units.h"
#include "isurface/fitting/akima_spline.h"
#include "isurface/fitting/interval_speed_plan.h"
#include "isurface/nc/feed_plan.h"
#include "isurface/optimise/eased_path.h"
#include "isurface/optimise/polyline_distance.h"
#include "isurface/optimise/rounded_corners.h"
#include "isurface/optimise/taut_path.h"

namespace isurface {

namespace {

// rad: each chord of a rounded corner turns the path by no more. The NC passes such a junction
// at the speeds of finishing without braking for its jerk; finer pieces only multiply lines.
constexpr double kRoundedPieceTurn = 0.1;

// mm: a bend is a stretch of moves shorter than this; a longer one is a straight (or the chord
// of a wide curve), whose corners are the planner's.
constexpr double kBendMoveLength = 1.0;

// Of the curvature at which the normal-acceleration bound holds the program's feed: where an
// eased bend is written in short pieces.
constexpr double kRampedBendShare = 0.25;

// The spline of one interval as G1 points: each of its segments (data point to data point) cut
// into equal pieces, so that the points keep the data points and are evenly spaced. A piece
// turns the path by at most `maxTurn` (rad) and strays at most `chordTolerance` (mm) from the
// curve: the NC then sees the smooth curvature of the spline at every junction instead of
// corners whose size depends on how the CAM system happened to space its points.
std::vector<Vec3> evenlySubdivided(const PiecewiseCubicCurve& curve, double chordTolerance, double maxTurn) {
  constexpr double kShortestPiece = 0.02;  // mm; finer pieces only multiply lines
  constexpr int kCurvatureChecks = 8;
  std::vector<Vec3> out;
  if (curve.empty()) return out;
  out.push_back(curve.segments().front().position(0));
  for (const CubicSegment& s : curve.segments()) {
    double curvature = 0;
    for (int k = 0; k <= kCurvatureChecks; ++k)
      curvature = std::max(curvature, curve.curvature(s.start + s.length * k / kCurvatureChecks));
    double piece = s.length;
    if (curvature > kZeroCurvature) {
      const double chordPiece = std::sqrt(8.0 * chordTolerance / curvature);  // sagitta of a chord
      piece = std::max(kShortestPiece, std::min(maxTurn / curvature, chordPiece));
    }
    const int count = std::max(1, static_cast<int>(std::ceil(s.length / piece - kRoundingSlack)));
    for (int k = 1; k <= count; ++k) out.push_back(s.position(s.length * k / count));
  }
  return out;
}

// The new G1 points of one interval. An Akima spline across a jump in point spacing (a long
// straight move met by short ones) swings away from the path, so the points are fitted in runs
// of similar spacing (ratio of neighbouring chords within the distance-ratio threshold); a run
// whose fit strays from its points by more than `maximumDeviation` keeps its points.
std::vector<Vec3> refitInterval(const std::vector<Vec3>& own, const OptimizeOptions& options) {
  std::vector<Vec3> out = {own.front()};
  const double ratio = options.thresholds.distanceRatio;
  std::size_t start = 0;
  for (std::size_t i = 1; i < own.size(); ++i) {
    const bool last = i + 1 == own.size();
    bool jump = false;
    if (!last) {
      const double before = (own[i] - own[i - 1]).norm(), after = (own[i + 1] - own[i]).norm();
      jump = after > ratio * before || before > ratio * after;
    }
    if (!jump && !last) continue;
    const std::vector<Vec3> run(own.begin() + start, own.begin() + i + 1);
    std::vector<Vec3> piece;
    if (run.size() >= 3) piece = evenlySubdivided(fitAkimaSpline(run), options.chordTolerance, options.maxTurn);
    if (piece.size() < 2 || polylineDistance(piece, run) > options.maximumDeviation) piece = run;
    out.insert(out.end(), piece.begin() + 1, piece.end());
    start = i;
  }
  return out;
}

// The pass's points fitted interval by interval, as the paper fits them.
std::vector<Vec3> fittedPath(const std::vector<Vec3>& points, const OptimizeOptions& options) {
  std::vector<Vec3> out = {points.front()};
  for (const ConstantSpeedInterval& interval : partitionConstantSpeedIntervals(points, options.thresholds).intervals) {
    const std::vector<Vec3> piece =
        refitInterval(std::vector<Vec3>(points.begin() + interval.first, points.begin() + interval.last + 1), options);
    out.insert(out.end(), piece.begin() + 1, piece.end());
  }
  return out;
}

// Per interval, the lowest feed ceiling among the old lines of the bend it belongs to, mm/s
// (infinite where there is none). A bend is a stretch of intervals of short moves; the servo
// deviates from a path where it bends, so the whole bend is held alike, whichever way the pass
// runs (a pass and its neighbour, cut the other way, then slow over the same stretch). A long
// straight move's corners are the planner's: slowing the whole move would only cost time.
// `moveOf`: per segment of the pass's points, the move of the run it stands for.
std::vector<double> bendCeilings(const OptimizeOptions& options, const Program& program, const std::vector<std::size_t>& run,
                                 const std::vector<std::size_t>& moveOf,
                                 const std::vector<ConstantSpeedInterval>& intervals) {
  const double none = std::numeric_limits<double>::infinity();
  std::vector<double> ceilings(intervals.size(), none);
  if (options.lineFeedCeiling.empty()) return ceilings;
  auto shortMoves = [&](const ConstantSpeedInterval& i) {
    return i.last > i.first && i.length / double(i.last - i.first) < kBendMoveLength;
  };
  for (std::size_t begin = 0; begin < intervals.size();) {
    std::size_t end = begin;
    while (end < intervals.size() && shortMoves(intervals[end])) ++end;
    double lowest = none;
    for (std::size_t k = begin; k < end; ++k)
      for (std::size_t i = intervals[k].first; i < intervals[k].last; ++i) {
        const std::uint32_t line = program.moves[run[moveOf[i]]].line;
        if (line < options.lineFeedCeiling.size() && options.lineFeedCeiling[line] > 0)
          lowest = std::min(lowest, mmPerMinToMmPerS(options.lineFeedCeiling[line]));
      }
    std::fill(ceilings.begin() + begin, ceilings.begin() + end, lowest);
    begin = std::max(end, begin + 1);
  }
  return ceilings;
}

// One feed per constant speed interval: the paper's planned speed from the interval's average
// curvature (interval_speed_plan.h), but no more than the NC allows over most of the new
// points (the median of its limits), so that the machine holds it rather than braking and
// speeding up at every point.
std::vector<double> intervalFeeds(const OptimizeOptions& options, const Program& program, const std::vector<std::size_t>& run,
                                  const std::vector<std::size_t>& moveOf, const std::vector<Vec3>& points, const std::vector<std::size_t>& dataIndex,
                                  const IntervalPartition& partition, double feed, const Machine& machine) {
  Program probe;
  probe.start = points.front();
  for (std::size_t k = 1; k < points.size(); ++k) {
    Move m;
    m.kind = MoveKind::Linear;
    m.end = points[k];
    m.feed = static_cast<float>(feed);
    m.line = static_cast<std::uint32_t>(k);
    probe.moves.push_back(m);
  }
  const FeedPlan plan = planFeed(probe, machine);
  // The limit at each new point and of each new segment, mm/s. The corners at an interval's
  // ends belong to the planner (it slows there whatever the feed): only what lies inside an
  // interval sets its feed.
  const double feedMmS = mmPerMinToMmPerS(feed);
  std::vector<double> atPoint(points.size(), feedMmS), ofSegment(points.size(), feedMmS);
  for (const PlannedSegment& s : plan.segments) {
    if (s.cornerReach > 0) {
      atPoint[s.move] = std::min(atPoint[s.move], s.cap);  // the blend at point k, where move k starts
      continue;
    }
    ofSegment[s.move] = std::min(ofSegment[s.move], s.cap);  // segment k runs from point k to k + 1
    if (s.move > 0) atPoint[s.move] = std::min(atPoint[s.move], s.entryLimit);
  }
  const std::vector<PlannedInterval> planned = planIntervalSpeeds(partition.intervals, feed, machine);
  const std::vector<double> ceilings = bendCeilings(options, program, run, moveOf, partition.intervals);
  std::vector<double> feeds;
  for (std::size_t k = 0; k < partition.intervals.size(); ++k) {
    const ConstantSpeedInterval& interval = partition.intervals[k];
    const std::size_t from = dataIndex[interval.first], to = dataIndex[interval.last];
    std::vector<double> limits(ofSegment.begin() + from, ofSegment.begin() + to);
    for (std::size_t k = from + 1; k < to; ++k) limits.push_back(atPoint[k]);
    std::sort(limits.begin(), limits.end());
    const double v = std::min({limits.empty() ? feedMmS : limits[limits.size() / 2],
                               mmPerMinToMmPerS(planned[k].plannedFeedMmMin), ceilings[k]});
    feeds.push_back(std::clamp(std::floor(options.feedScale * mmPerSToMmPerMin(v)), 0.2 * feed, feed));
  }
  return feeds;
}

// One pass re-fitted and its interval feeds planned (the paper's steps, pass by pass).
PassFeeds planPass(const Program& program, const std::vector<std::size_t>& run, const Machine& machine,
                   const OptimizeOptions& options, FittedBox& fitted) {
  std::vector<Vec3> points = {program.startOf(run.front())};
  for (std::size_t i : run) points.push_back(program.moves[i].end);
  // Per segment of `points`, the move of the run it stands for.
  std::vector<std::size_t> moveOf(points.size() - 1);
  std::iota(moveOf.begin(), moveOf.end(), std::size_t{0});
  if (options.shape == PathShape::DrawnTaut) points = drawnTaut(points, options.maximumDeviation);
  if (options.shape == PathShape::CornersRounded) {
    RoundedPath rounded = roundedCorners(points, options.maximumDeviation, kRoundedPieceTurn);
    points = std::move(rounded.points);
    moveOf = std::move(rounded.oldSegment);
  }
  if (options.shape == PathShape::Eased) {
    EasingLimits limits{options.maximumDeviation, options.chordTolerance, options.maxTurn, INFINITY};
    const double feed = mmPerMinToMmPerS(program.moves[run.front()].feed);  // mm/s
    // The bound holds the feed below the program's where the curvature passes limit / F^2; the
    // ramps into such a bend run where it is a few times gentler.
    if (options.normalAccelerationLimit > 0 && feed > 0)
      limits.bendCurvature = kRampedBendShare * options.normalAccelerationLimit / (feed * feed);
    // Eased the same way whichever way the pass runs, then turned back: the fit of a pass and
    // its neighbour cut the other way (a zig-zag) would otherwise put their bends a little apart.
    const bool backwards = runsBackwards(points.front(), points.back());
    if (backwards) std::reverse(points.begin(), points.end());
    EasedPath eased = easedPath(fittedPath(points, options), points, limits);
    if (backwards) {
      std::reverse(eased.points.begin(), eased.points.end());
      std::reverse(eased.oldSegment.begin(), eased.oldSegment.end());
      for (std::size_t& segment : eased.oldSegment) segment = points.size() - 2 - segment;
    }
    std::vector<std::size_t> moves;
    for (const std::size_t segment : eased.oldSegment) moves.push_back(moveOf[segment]);
    points = std::move(eased.points);
    moveOf = std::move(moves);
  }
  const IntervalPartition partition = partitionConstantSpeedIntervals(points, options.thresholds);
  // Each constant speed interval is fitted on its own (as the paper fits the CL points of an
  // interval): a spline across an interval's boundary, where spacing or curvature jumps,
  // would swing away from the path. An interval whose fit strays from its points by more
  // than half the tolerance of the check keeps its points.
  PassFeeds plan;
  plan.points = {points.front()};
  std::vector<std::size_t> dataIndex(points.size(), 0);
  for (const ConstantSpeedInterval& interval : partition.intervals) {
    const std::vector<Vec3> own(points.begin() + interval.first, points.begin() + interval.last + 1);
    // A path drawn taut, rounded or eased has used the deviation a fit would be allowed: it is
    // not fitted (again).
    const std::vector<Vec3> piece = options.shape != PathShape::Fitted ? own : refitInterval(own, options);
    const std::size_t offset = plan.points.size() - 1;
    plan.points.insert(plan.points.end(), piece.begin() + 1, piece.end());
    for (std::size_t i = interval.first, j = 0; i <= interval.last; ++i) {
      while (j + 1 < piece.size() && (piece[j] - points[i]).norm() > kLengthEpsilon) ++j;
      dataIndex[i] = offset + j;
    }
    plan.intervalEnd.push_back(plan.points.size() - 1);
    if (own.size() >= 3 && interval.averageCurvature > 1e-3 && interval.length / (own.size() - 1) < 1.0)
      for (const Vec3& p : own) fitted.add(p);
  }
  plan.sourceLines.assign(plan.points.size(), 0);
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    for (std::size_t k = dataIndex[i] + 1; k <= dataIndex[i + 1] && k < plan.points.size(); ++k)
      plan.sourceLines[k] = program.moves[run[moveOf[i]]].line;
  const double feed = program.moves[run.front()].feed;
  plan.feeds = options.programmedFeed
                   ? std::vector<double>(partition.intervals.size(),
                                         options.feedCap > 0 ? std::clamp(std::floor(options.feedCap), 1.0, feed) : feed)
                   : intervalFeeds(options, program, run, moveOf, plan.points, dataIndex, partition, feed, machine);
  return plan;
}

}  // namespace

// Every pass planned, the later half on a second core: the passes are planned each on its own.
std::vector<PassFeeds> planPasses(const Program& program, const std::vector<std::vector<std::size_t>>& runs,
                                  const Machine& machine, const OptimizeOptions& options, FittedBox& fitted) {
  auto plan = [&](std::size_t first, std::size_t last, FittedBox& box) {
    std::vector<PassFeeds> plans;
    for (std::size_t r = first; r < last; ++r) plans.push_back(planPass(program, runs[r], machine, options, box));
    return plans;
  };
  const std::size_t middle = runs.size() / 2;
  FittedBox laterBox;
  std::future<std::vector<PassFeeds>> later = std::async(std::launch::async, plan, middle, runs.size(), std::ref(laterBox));
  std::vector<PassFeeds> plans = plan(0, middle, fitted);
  for (PassFeeds& p : later.get()) plans.push_back(std::move(p));
  if (!laterBox.empty) fitted.add(laterBox.lower), fitted.add(laterBox.upper);
  return plans;
}

}  // namespace isurface
