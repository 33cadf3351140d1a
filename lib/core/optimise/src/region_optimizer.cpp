#include "isurface/optimise/region_optimizer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string_view>

#include <fmt/format.h>

#include "isurface/optimise/polyline_distance.h"
#include "isurface/fitting/akima_spline.h"
#include "isurface/base/diagnostic.h"
#include "isurface/base/tolerances.h"
#include "isurface/base/units.h"
#include "isurface/nc/feed_plan.h"
#include "isurface/fitting/interval_speed_plan.h"
#include "isurface/analysis/quantities.h"
#include "isurface/optimise/cross_pass_feeds.h"
#include "isurface/optimise/eased_path.h"
#include "isurface/optimise/feed_ramps.h"
#include "isurface/optimise/points_on_grid.h"
#include "isurface/optimise/rounded_corners.h"
#include "isurface/optimise/speeds_across_passes.h"
#include "isurface/optimise/stretch_across_box.h"
#include "isurface/optimise/taut_path.h"

namespace isurface {

namespace {

// rad: each chord of a rounded corner turns the path by no more. The NC passes such a junction
// at the speeds of finishing without braking for its jerk; finer pieces only multiply lines.
constexpr double kRoundedPieceTurn = 0.1;

// mm: a bend is a stretch of moves shorter than this; a longer one is a straight (or the chord
// of a wide curve), whose corners are the planner's.
constexpr double kBendMoveLength = 1.0;
// Of the machine's acceleration (its slowest axis), the ramps' outside the region's box.
constexpr double kOutsideRampShare = 0.5;
// Of the curvature at which the normal-acceleration bound holds the program's feed: where an
// eased bend is written in short pieces.
constexpr double kRampedBendShare = 0.25;
// Of a pass's feed, how much faster a point of it may run than the pass beside it.
constexpr double kSpeedStepAcrossPasses = 0.015;

// The program's physical lines, each with its own line end, so unchanged ones are copied
// byte for byte.
std::vector<std::string_view> splitLines(const std::string& text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::size_t stop = end == std::string::npos ? text.size() : end + 1;
    lines.emplace_back(text.data() + start, stop - start);
    start = stop;
  }
  return lines;
}

// A line that holds nothing but a straight feed move (G1, coordinates, feed, block number,
// comments): it can be replaced without losing anything else it says.
bool plainFeedLine(std::string_view line) {
  int depth = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == ';') break;
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (depth > 0 || c == ')') continue;
    const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (std::isalpha(static_cast<unsigned char>(u))) {
      if (u == 'G') {
        std::size_t j = i + 1;
        while (j < line.size() && line[j] == ' ') ++j;
        std::string number;
        while (j < line.size() && (std::isdigit(static_cast<unsigned char>(line[j])) || line[j] == '.')) number += line[j++];
        if (number != "1" && number != "01") return false;
      } else if (u != 'X' && u != 'Y' && u != 'Z' && u != 'F' && u != 'N') {
        return false;
      }
    }
  }
  return true;
}

bool mentions(const std::string& text, const char* code) {
  std::string upper(text.size(), ' ');
  std::transform(text.begin(), text.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
  std::size_t at = 0;
  const std::size_t n = std::string_view(code).size();
  while ((at = upper.find(code, at)) != std::string::npos) {
    const char next = at + n < upper.size() ? upper[at + n] : ' ';
    if (!std::isdigit(static_cast<unsigned char>(next)) && next != '.') return true;
    at += n;
  }
  return false;
}

// Whether unit directions `a` and `b` turn sharply seen from above, or either runs (nearly)
// vertically: a step-over, a plunge or a lift, where a pass ends even though its points may
// step up and down in Z at every point.
bool sharpTurnInPlan(const Vec3& a, const Vec3& b) {
  constexpr double kSteep = 0.1;  // of a unit direction's length: steeper than 84 degrees
  const Eigen::Vector2d inPlanA = a.head<2>(), inPlanB = b.head<2>();
  if (inPlanA.norm() < kSteep || inPlanB.norm() < kSteep) return true;
  return inPlanA.normalized().dot(inPlanB.normalized()) < 0.5;
}

// Runs of consecutive plain G1 moves in the range, split where the path turns back in XY (the
// end of a raster pass) and at sharp corners (a step-over), around which a spline would swing.
// A path drawn taut or rounded softens a corner within its tube like any other point, so for
// them only a corner seen from above ends a run, not one in Z.
std::vector<std::vector<std::size_t>> findRuns(const Program& program, const std::vector<std::string_view>& lines,
                                               LineRange range, bool onlyCornersInPlanEndRuns) {
  std::vector<std::vector<std::size_t>> runs;
  std::vector<std::size_t> run;
  auto close = [&] {
    if (!run.empty()) runs.push_back(run);
    run.clear();
  };
  for (std::size_t i = 0; i < program.moves.size(); ++i) {
    const Move& m = program.moves[i];
    const bool sharesLine = (i > 0 && program.moves[i - 1].line == m.line) ||
                            (i + 1 < program.moves.size() && program.moves[i + 1].line == m.line);
    const bool usable = m.kind == MoveKind::Linear && m.line >= range.first && m.line <= range.last &&
                        m.line <= lines.size() && !sharesLine && !(m.flags & (kExactStop | kStopAfter)) &&
                        plainFeedLine(lines[m.line - 1]);
    if (!usable) {
      close();
      continue;
    }
    if (!run.empty()) {
      const Move& previous = program.moves[run.back()];
      const Vec3 a = (previous.end - program.startOf(run.back())).normalized();
      const Vec3 b = (m.end - program.startOf(i)).normalized();
      const Vec3 main = program.moves[run.front()].end - program.startOf(run.front());
      const bool consecutive = m.line == previous.line + 1;
      const bool corner = onlyCornersInPlanEndRuns ? sharpTurnInPlan(a, b) : a.dot(b) < 0.5;
      const bool turnsBack = main.x() * b.x() + main.y() * b.y() < 0;
      if (!consecutive || corner || turnsBack || m.feed != previous.feed) close();
    }
    run.push_back(i);
  }
  close();
  return runs;
}

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

// One feed per constant speed interval: the paper's planned speed from the interval's average
// curvature (interval_speed_plan.h), but no more than the NC allows over most of the new
// points (the median of its limits), so that the machine holds it rather than braking and
// speeding up at every point.
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
    ofSegment[s.move] = std::min(feedMmS, s.cap);  // segment k runs from point k to k + 1
    if (s.move > 0) atPoint[s.move] = std::min(feedMmS, s.entryLimit);
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

// New blocks in the program's own units: mm with 4 decimals and whole mm/min, or inches with
// 5 decimals (0.25 um) and in/min with 2.
struct BlockUnits {
  double perMm;  // program units per mm
  int positionDecimals, feedDecimals;
  std::string position(const Vec3& p) const {
    return fmt::format("X{:.{}f} Y{:.{}f} Z{:.{}f}", p.x() * perMm, positionDecimals, p.y() * perMm, positionDecimals,
                       p.z() * perMm, positionDecimals);
  }
  std::string feed(double mmPerMin) const { return fmt::format("{:.{}f}", mmPerMin * perMm, feedDecimals); }
  double grid() const { return std::pow(10.0, -positionDecimals) / perMm; }  // mm, the last decimal's step
};

// Where the path was re-fitted: dense, curved intervals (the transition a region is about,
// not its long straight runs), mm.
struct FittedBox {
  bool empty = true;
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();
  void add(const Vec3& p) {
    lower = empty ? p : lower.cwiseMin(p);
    upper = empty ? p : upper.cwiseMax(p);
    empty = false;
  }
};

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

// How a pass's feeds are ramped: inside the region's box at the ramp's acceleration, outside at
// half the machine's (its slowest axis), if that is faster. `feed`: the pass's, mm/min.
RampOptions rampOptions(const OptimizeOptions& options, double feed, const Machine& machine) {
  double slowestAxis = INFINITY;  // mm/s^2
  for (const AxisLimits& axis : machine.axes) slowestAxis = std::min(slowestAxis, axis.maxAcceleration);
  RampOptions ramps;
  ramps.programmedFeed = feed;
  ramps.normalAccelerationLimit = options.normalAccelerationLimit;
  ramps.rampAcceleration = options.rampAcceleration;
  ramps.within = options.rampBox;
  ramps.outsideAcceleration = kOutsideRampShare * slowestAxis;
  return ramps;
}

// Each pass's feeds per move, its bends' ramps held where they would run faster than the
// passes beside them (speeds_across_passes.h).
std::vector<FeedPerMove> feedsAgreeingAcrossPasses(const std::vector<PassFeeds>& plans, const std::vector<std::vector<std::size_t>>& runs,
                                                   const Program& program, const OptimizeOptions& options, const Machine& machine) {
  std::vector<double> programmedFeeds;  // mm/min
  std::vector<FeedPerMove> moves;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    programmedFeeds.push_back(program.moves[runs[r].front()].feed);
    moves.push_back(feedPerMove(plans[r], rampOptions(options, programmedFeeds[r], machine)));
  }
  if (!(options.rampAcceleration > 0 && options.normalAccelerationLimit > 0)) return moves;
  const std::vector<std::vector<double>> caps = speedCapsAcrossPasses(moves, programmedFeeds, {kSpeedStepAcrossPasses});
  for (std::size_t r = 0; r < runs.size(); ++r)
    // A pass no neighbour holds ramps as it did.
    if (std::any_of(caps[r].begin(), caps[r].end(), [](double cap) { return std::isfinite(cap); }))
      moves[r] = feedPerMoveHeldTo(plans[r], moves[r], caps[r], rampOptions(options, programmedFeeds[r], machine));
  return moves;
}

}  // namespace

OptimizeResult optimizeRegion(const std::string& text, const Program& program, LineRange range,
                              const Machine& machine, const OptimizeOptions& options) {
  if (mentions(text, "G91")) throw InputError(Diagnostic{program.source, 0, 0, "incremental programs (G91) are not re-optimised"});
  // An inch program is re-fitted in mm, as it was read, and its new blocks are written back in
  // inches; one that switches units part way is refused rather than guessed at.
  const bool inch = mentions(text, "G20");
  if (inch && mentions(text, "G21"))
    throw InputError(Diagnostic{program.source, 0, 0,
                                "programs that switch between inches and millimetres (G20 and G21) are not re-optimised"});
  const BlockUnits units = inch ? BlockUnits{1.0 / kMmPerInch, 5, 2} : BlockUnits{1.0, 4, 0};
  if (mentions(text, "G93")) throw InputError(Diagnostic{program.source, 0, 0, "inverse-time programs (G93) are not re-optimised"});
  const std::vector<std::string_view> lines = splitLines(text);
  std::vector<std::vector<std::size_t>> runs =
      findRuns(program, lines, range, options.shape == PathShape::DrawnTaut || options.shape == PathShape::CornersRounded);
  if (options.planBox)
    for (auto& run : runs) run = stretchAcrossBox(program, run, *options.planBox);
  runs.erase(std::remove_if(runs.begin(), runs.end(), [&](const auto& r) { return r.size() < options.minimumMoves; }),
             runs.end());
  if (runs.empty())
    throw InputError(Diagnostic{program.source, range.first, 0,
                                fmt::format("lines {}-{} hold no run of {} or more plain G1 moves to re-optimise",
                                            range.first, range.last, options.minimumMoves)});
  OptimizeResult result;
  FittedBox fittedBox;
  std::uint32_t written = 0;  // lines of the output so far
  std::size_t nextSource = 1; // next source line to copy
  const char* lineEnd = text.find("\r\n") != std::string::npos ? "\r\n" : "\n";
  auto copyUntil = [&](std::size_t lastLine) {
    for (; nextSource <= lastLine && nextSource <= lines.size(); ++nextSource) {
      result.text.append(lines[nextSource - 1]);
      ++written;
    }
  };
  // First every pass is re-fitted and its interval feeds planned; then the feeds are planned
  // across passes; then the passes are written.
  const std::string how = options.shape == PathShape::DrawnTaut
                             ? fmt::format("points drawn taut within {:g} mm", options.maximumDeviation)
                         : options.shape == PathShape::CornersRounded
                             ? fmt::format("corners rounded within {:g} mm", options.maximumDeviation)
                         : options.shape == PathShape::Eased
                             ? fmt::format("Akima spline in arc length, bends eased in and out within {:g} mm", options.maximumDeviation)
                             : std::string("Akima spline in arc length");
  std::vector<PassFeeds> plans;
  for (const auto& run : runs) plans.push_back(planPass(program, run, machine, options, fittedBox));
  result.fittedLower = fittedBox.lower;
  result.fittedUpper = fittedBox.upper;
  harmonizeFeedsAcrossPasses(plans, options.crossPass);
  const std::vector<FeedPerMove> movesOfPasses = feedsAgreeingAcrossPasses(plans, runs, program, options, machine);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const auto& run = runs[r];
    const Move& first = program.moves[run.front()];
    const Move& last = program.moves[run.back()];
    const FeedPerMove& moves = movesOfPasses[r];
    const double feed = first.feed;
    const std::vector<double>& feeds = plans[r].feeds;
    copyUntil(first.line - 1);
    OptimizedPass pass;
    pass.firstLine = first.line;
    pass.lastLine = last.line;
    pass.oldMoves = run.size();
    pass.intervalFeeds = feeds;
    // One feed per interval, or the program's own (perhaps capped) for the whole pass.
    std::string feedList = options.programmedFeed ? ", feed F" + units.feed(feeds.front()) : ", constant speed intervals";
    if (!options.programmedFeed)
      for (double f : feeds) feedList += " F" + units.feed(f);
    result.text += fmt::format("(iSurface: lines {}-{} re-fitted: {}{}{}){}", first.line, last.line, how, feedList,
                               options.rampAcceleration > 0 ? fmt::format(", ramps of {:g} mm/s^2", options.rampAcceleration) : "",
                               lineEnd);
    pass.newFirstLine = ++written;
    // An eased path is smooth and written in short pieces: its points are placed where their
    // rounding keeps them on it. (The paper's fit is written as it is: placed so, its runs on
    // samples/wuzhishan.nc ran 4 % faster instead of 2 % and the servo deviated 6 % more. A
    // taut or rounded path keeps corners a parabola would cut.)
    const std::vector<Vec3> onGrid =
        options.shape == PathShape::Eased ? pointsOnGrid(moves.points, units.grid()) : moves.points;
    std::string current;
    for (std::size_t k = 1; k < moves.points.size(); ++k) {
      const std::string f = units.feed(moves.feeds[k - 1]);
      std::string block = "G1 " + units.position(onGrid[k]);
      if (f != current) block += " F" + f, current = f;
      result.text += block + lineEnd;
      pass.sourceLines.push_back(moves.sourceLines[k]);
      ++written;
      ++pass.newMoves;
    }
    // The lines after keep the feed they had.
    if (current != units.feed(feed)) {
      result.text += "F" + units.feed(feed) + lineEnd;
      ++written;
    }
    pass.newLastLine = written;
    nextSource = last.line + 1;
    result.passes.push_back(pass);
  }
  copyUntil(lines.size());
  // Lines of the range before its first pass keep their numbers; those after its last pass
  // moved by what the passes added.
  const OptimizedPass& lastPass = result.passes.back();
  result.newRange.first = std::min(range.first, result.passes.front().newFirstLine);
  result.newRange.last = range.last > lastPass.lastLine
                             ? static_cast<std::uint32_t>(range.last + (lastPass.newLastLine - lastPass.lastLine))
                             : lastPass.newLastLine;
  return result;
}

LineRange linesOfPass(const Trajectory& samples, const Pass& pass) {
  LineRange r{UINT32_MAX, 0};
  samples.line.forEachRun(pass.begin, pass.end, [&](std::uint32_t line, std::size_t, std::size_t) {
    if (line != 0) r.first = std::min(r.first, line), r.last = std::max(r.last, line);
  });
  return r;
}

LineRange widenToWholePasses(const Trajectory& samples, const PassSet& passSet, LineRange lines) {
  const std::vector<Pass>& passes = passSet.passes;
  auto lineRangeOf = [&](const Pass& p) { return linesOfPass(samples, p); };
  std::size_t first = passes.size(), last = 0;
  for (std::size_t k = 0; k < passes.size(); ++k) {
    const LineRange r = lineRangeOf(passes[k]);
    if (r.last < lines.first || r.first > lines.last) continue;
    first = std::min(first, k), last = std::max(last, k);
  }
  if (first > last) return lines;
  const LineRange from = lineRangeOf(passes[first > 0 ? first - 1 : first]);
  const LineRange to = lineRangeOf(passes[last + 1 < passes.size() ? last + 1 : last]);
  return {std::min(lines.first, from.first), std::max(lines.last, to.last)};
}

}  // namespace isurface
