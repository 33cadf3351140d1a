#include "isurface/nc/feed_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "isurface/base/diagnostic.h"
#include "isurface/base/tolerances.h"
#include "isurface/base/units.h"
#include "isurface/gcode/path_segment.h"

#include "chord_run.h"
#include "corner_blend.h"
#include "generic_limits.h"

#include <fmt/format.h>

namespace isurface {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A single move or dwell longer than this (s) is a mistake in the program, not machining: it
// would make billions of samples.
constexpr double kLongestMove = 24 * 3600.0;
// A G1 move is a chord of a curve the control may smooth when it is at most this long (mm), and
// two chords join in a curve when they turn by at most this much (rad): CAM chords of a finishing
// pass are 0.01-2 mm and turn by a few degrees; a longer move or a sharper turn is the
// program's own corner.
constexpr double kLongestChord = 5.0;
constexpr double kLargestChordTurn = 0.35;

std::string speedName(float feedMmMin) {
  return feedMmMin < 0 ? std::string("at the machine's rapid speed") : fmt::format("at F{:g}", feedMmMin);
}

// Plans move by move. Each segment is first "closed" once the next one is known (its end
// junction's limit, hence its share of acceleration and the forward pass's speed at its end,
// depend on the next segment); the backward pass then settles the speeds of closed segments.
// planFeed runs it once over the whole program; the streaming planner over a window, assuming
// a stop at the window's end, and hands out only the segments that this assumption cannot
// change (see commit()). Both do the same floating-point operations in the same order.
class Planner {
 public:
  Planner(const Machine& machine, const LimitBudget& budget, std::string source)
      : machine_(machine), budget_(budget), source_(std::move(source)), limits_(machine, budget) {}

  double filterTime1() const { return limits_.filterTime1(); }
  double filterTime2() const { return limits_.filterTime2(); }
  double holdBefore() const { return holdBefore_; }
  std::size_t held() const { return window_.size() - head_; }
  std::size_t forcedCommits() const { return forcedCommits_; }
  std::uint64_t closedSegments() const { return closedSegments_; }
  bool finished() const { return finished_; }

  // Move `index`, which starts at `start`. A chord the control may run as a curve waits for the
  // move after it, which sets the curve's direction at its end.
  void add(std::uint32_t index, const Move& move, const Vec3& start) {
    if (move.kind == MoveKind::Dwell) {
      const double seconds = std::max(0.0, move.dwellSeconds());
      if (seconds > kLongestMove)
        throw InputError(Diagnostic{source_, move.line, move.column,
                                    fmt::format("a dwell of {:.4g} s is longer than {:.0f} h: not a real program",
                                                seconds, kLongestMove / 3600)});
      endRun();
      if (segments_ == 0) holdBefore_ += seconds;
      else window_.back().planned.holdAfter += seconds;
      stopAtJunction();
      return;
    }
    const PathSegment seg = PathSegment::from(start, move);
    if (seg.length > 0) {
      if (smoothsChords_ && isChord(move, seg)) {
        if (!run_.empty() && !chordsJoinSmoothly(lastChord_, seg)) endRun();
        run_.push(index, move, seg);
        lastChord_ = seg;
        planSettledChords();
      } else {
        endRun();
        addPiece(index, move, seg, nullptr);
      }
    }
    if (move.flags & (kExactStop | kStopAfter)) {
      endRun();
      stopAtJunction();
    }
  }

  // The program has ended: the machine comes to rest after the last segment.
  void finish() {
    endRun();
    finished_ = true;
    if (segments_ == 0) return;
    close(window_.back(), 0.0, junctionRadius_);  // v[n] = 0
    ++closed_;
    ++closedSegments_;
  }

  // Settles the speeds of the closed segments and appends those that are final to `out`.
  //
  // The backward pass gives junction k the speed v[k] = min(f[k], sqrt(v[k+1]^2 + 2 a L)), f
  // being the forward pass's. Assuming a stop at the window's end gives speeds w[k] <= v[k]
  // (floating-point sqrt, + and min are monotonic). Where w[j] == f[j], v[j] == f[j] too, and
  // every junction before j is computed from it exactly as the whole program's pass does: the
  // segments before the last such j are final. At the program's end the stop is real.
  //
  // A window that would still hold more than maxHeld segments after that (a braking distance
  // spanning that many segments) commits all but maxHeld / 2 of them with the stop assumed,
  // which only slows it down, and counts it in forcedCommits(); the forward pass is redone
  // from there.
  void commit(std::vector<PlannedSegment>& out, std::size_t maxHeld = kUnbounded) {
    const std::size_t m = closed_ - head_;
    if (m == 0) return;
    const double endForward = finished_ && closed_ == window_.size() ? 0.0 : window_[closed_].entryForward;
    speeds_.resize(m + 1);
    speeds_[m] = 0.0;
    std::size_t last = endForward == 0.0 ? m : 0;  // the last junction whose speed is final
    for (std::size_t k = m; k-- > 1;) {
      const Entry& e = window_[head_ + k];
      speeds_[k] = std::min(e.entryForward,
                            std::sqrt(speeds_[k + 1] * speeds_[k + 1] + 2.0 * e.planned.accel * e.planned.length));
      if (last == 0 && speeds_[k] == e.entryForward) last = k;
    }
    speeds_[0] = window_[head_].entryForward;
    bool forced = false;
    if (held() - last > maxHeld) {
      const std::size_t keep = maxHeld / 2;
      if (m > keep && m - keep > last) {
        last = m - keep;
        forced = true;
        ++forcedCommits_;
      }
    }
    for (std::size_t k = 0; k < last; ++k) {
      PlannedSegment& s = window_[head_ + k].planned;
      s.entrySpeed = speeds_[k];
      s.exitSpeed = speeds_[k + 1];
      const double reachable =
          std::sqrt(s.accel * s.length + 0.5 * (s.entrySpeed * s.entrySpeed + s.exitSpeed * s.exitSpeed));
      s.peakSpeed = std::max({std::min(s.cap, reachable), s.entrySpeed, s.exitSpeed});
      if (s.motionTime() > kLongestMove)
        throw InputError(Diagnostic{source_, window_[head_ + k].line, window_[head_ + k].column,
                                    fmt::format("this move takes {:.3g} h {}: an impossible speed for {:.4g} mm",
                                                s.motionTime() / 3600, speedName(window_[head_ + k].feedMmMin), s.length)});
      out.push_back(s);
    }
    head_ += last;
    if (forced) redoForward(speeds_[last]);
    if (head_ > 4096 && head_ > window_.size() / 2) {
      window_.erase(window_.begin(), window_.begin() + static_cast<std::ptrdiff_t>(head_));
      closed_ -= head_;
      head_ = 0;
    }
  }

  static constexpr std::size_t kUnbounded = std::numeric_limits<std::size_t>::max();

 private:
  struct Entry {
    PlannedSegment planned;   // cap and entryLimit (the start junction's limit) set when added
    double axisAccel = 0;     // mm/s^2 along it that its axes allow, no shares
    double accelCap = kInfinity;  // mm/s^2, its ramps' limit on a tight arc (curveAccelLimit)
    double centripetal = 0;   // mm/s^2 on an arc at its speed cap
    double entryRadius = 0;   // mm, three-point radius at its start junction between lines
    double entryForward = 0;  // mm/s, the forward pass's speed at its start
    std::uint32_t line = 0;   // of its move, for messages
    float feedMmMin = 0;      // mm/min, its move's F word as programmed (for messages); < 0: a rapid
    std::uint16_t column = 0; // of its move, for messages
  };

  // A G1 chord that may join its neighbours in a curve (chord_spline.h), and whether two may.
  static bool isChord(const Move& move, const PathSegment& seg) {
    return move.kind == MoveKind::Linear && seg.length <= kLongestChord;
  }
  static bool chordsJoinSmoothly(const PathSegment& in, const PathSegment& out) {
    return in.direction.dot(out.direction) >= std::cos(kLargestChordTurn);
  }

  // The run of chords ends at the last one pushed.
  void endRun() {
    if (run_.empty()) return;
    run_.end();
    planSettledChords();
  }

  // Plans the chords of the run whose curve is settled. Each is run as the curve through its
  // fitted ends where that stays within the machine's tolerance of the chord; else as the
  // straight line between the same ends, turning at them as at any corner.
  void planSettledChords() {
    run_.take(fitted_);
    for (const FittedChord& c : fitted_) {
      if (!c.start || !c.end) {
        addPiece(c.index, c.move, c.seg, nullptr);
        continue;
      }
      std::array<float, 18> packed = packCurve(*c.start, *c.end);
      ChordSpline curve = curveOf(c.seg, packed);
      ChordSpline::Shape shape = curve.shape();
      if (!shape.wellFormed || !(curve.farthestFrom(c.seg.start, c.seg.end) <= limits_.smoothingTolerance())) {
        CurveEnd start = *c.start, end = *c.end;
        start.knot = end.knot = ChordKnot::straight(c.seg.start + start.offset, c.seg.end + end.offset);
        packed = packCurve(start, end);
        curve = curveOf(c.seg, packed);
        shape = curve.shape();
      }
      const PlannedCurve planned{curve, shape};
      addPiece(c.index, c.move, c.seg, &planned);
      window_.back().planned.smooth = true;
      window_.back().planned.chordCurve = packed;
    }
    fitted_.clear();
  }

  struct PlannedCurve {
    ChordSpline curve;
    ChordSpline::Shape shape;
  };

  // A move's segment, after its start junction: run as `curve` where it is not null.
  void addPiece(std::uint32_t index, const Move& move, const PathSegment& seg, const PlannedCurve* curve) {
    const Vec3 startTangent = curve ? curve->curve.startTangent() : seg.startTangent();
    double reach = 0;
    if (segments_ > 0) {
      double hold = 0;
      const GenericLimits::Junction junction{previousEndTangent_, startTangent,
                                             !previousCurve_ && !curve && !previous_.arc && !seg.arc};
      const double limit =
          limits_.cornerLimit(previous_, seg, junction, window_.back().planned.accel, hold, junctionRadius_);
      // A blend where it passes the corner faster than the filters' rounding of it does; none
      // at a rapid or where a stop is planned.
      const bool blendable = machine_.control.chordSmoothing && !stopped_ && junctionLimit_ > 0 && !previousRapid_ &&
                             move.kind != MoveKind::Rapid && !previousCurve_ && !curve;
      const BlendChoice blend = blendable ? limits_.blendAt(previous_, seg, move) : BlendChoice{};
      if (blend.reach > 0 && blend.speed > limit) {
        reach = blend.reach;
        junctionRadius_ = kInfinity;
        addBlend(index, move, seg, blend);
      } else if (limit > 0) {
        junctionLimit_ = std::min(junctionLimit_, limit);
      } else {
        stopAtJunction(hold);
      }
    }
    if (curve) addCurve(index, move, *curve);
    else addSegment(index, move, reach > 0 ? shortenedLine(seg, reach, 0.0) : seg, reach);
    previous_ = seg;
    previousEndTangent_ = curve ? curve->curve.endTangent() : seg.endTangent();
    previousCurve_ = curve != nullptr;
    previousRapid_ = move.kind == MoveKind::Rapid;
  }

  void addCurve(std::uint32_t index, const Move& move, const PlannedCurve& curve) {
    Entry e;
    PlannedSegment& ps = e.planned;
    ps.move = index;
    ps.length = curve.curve.length();
    const ChordSpline::Shape& shape = curve.shape;
    ps.accel = limits_.chordCurveAccel(shape);
    const double radius = shape.largestCurvature > 0 ? 1.0 / shape.largestCurvature : kInfinity;
    append(e, move, limits_.chordCurveSpeed(shape, move), limits_.curveAccelLimit(radius, limits_.smoothingTolerance()));
  }

  // The machine comes to rest at the current junction and waits `hold` seconds; by default
  // until the filters have drained, so that the corner is reached exactly (an exact stop, as
  // in-position checking does).
  void stopAtJunction(double hold = -1) {
    if (hold < 0) hold = limits_.settleTime();
    junctionLimit_ = 0.0;
    if (segments_ > 0) {
      double& planned = window_.back().planned.holdAfter;
      planned = stopped_ ? std::max(planned, hold) : planned + hold;
    }
    stopped_ = true;
  }

  // The blend at the corner where `out` (move `index`) starts: the last segment gives up its
  // reach at its end.
  void addBlend(std::uint32_t index, const Move& move, const PathSegment& out, const BlendChoice& choice) {
    const CornerBlend blend = *CornerBlend::at(out.start, previous_.direction, out.direction, choice.reach);
    PlannedSegment& before = window_.back().planned;
    before.length = std::max(0.0, before.length - choice.reach);
    before.trimEnd = choice.reach;
    Entry e;
    PlannedSegment& ps = e.planned;
    ps.move = index;
    ps.length = blend.length();
    ps.cornerReach = choice.reach;
    ps.accel = limits_.blendAccel(blend);
    e.centripetal = choice.speed * choice.speed / blend.radius();
    append(e, move, choice.speed, limits_.curveAccelLimit(blend.radius(), choice.filterTolerance));
  }

  void addSegment(std::uint32_t index, const Move& move, const PathSegment& seg, double trimStart) {
    Entry e;
    PlannedSegment& ps = e.planned;
    ps.move = index;
    ps.length = seg.length;
    ps.trimStart = trimStart;
    const double speed = limits_.segmentSpeed(seg, move);
    // The feed and the axes' speeds are honoured however slow; only a curve's own limits have a
    // floor (kSlowestSpeed), so that degenerate geometry is still passed in finite time.
    if (!(speed > 0))
      throw InputError(Diagnostic{source_, move.line, move.column,
                                  move.kind == MoveKind::Rapid ? "the machine's rapid speed is not above 0"
                                                               : fmt::format("feed F{:g} is not above 0", move.feed)});
    ps.accel = limits_.tangentialAccel(seg);
    e.centripetal = seg.arc ? speed * speed / std::max(seg.arcGeometry.minRadius(), kLengthEpsilon) : 0.0;
    append(e, move, speed,
           seg.arc ? limits_.curveAccelLimit(seg.arcGeometry.minRadius(), limits_.smoothingTolerance()) : kInfinity);
  }

  // Adds a segment whose geometry's limits are set in `e` (its length, ramps' acceleration and
  // centripetal acceleration): its speed limit `speed` (mm/s) and ramps' limit `accelCap`.
  void append(Entry& e, const Move& move, double speed, double accelCap) {
    PlannedSegment& ps = e.planned;
    ps.peakSpeed = speed;  // the cap until commit() settles the profile
    ps.cap = speed;
    e.axisAccel = ps.accel / budget_.tangentialAccel;
    e.accelCap = accelCap;
    ps.accel = std::min(ps.accel, e.accelCap);
    e.entryRadius = junctionRadius_;
    if (segments_ == 0) {
      ps.entryLimit = 0.0;  // the machine starts at rest
      e.entryForward = 0.0;
    } else {
      Entry& before = window_.back();
      ps.entryLimit = std::min({junctionLimit_, before.planned.cap, speed});
      close(before, ps.entryLimit, e.entryRadius);
      ++closed_;
      ++closedSegments_;
      e.entryForward = std::min(ps.entryLimit, std::sqrt(before.entryForward * before.entryForward +
                                                         2.0 * before.planned.accel * before.planned.length));
    }
    e.line = move.line;
    e.column = move.column;
    e.feedMmMin = move.kind == MoveKind::Rapid ? -1.0f : move.feed;
    window_.push_back(e);
    ++segments_;
    junctionLimit_ = kInfinity;
    junctionRadius_ = kInfinity;
    stopped_ = false;
  }

  // Once its end junction's limit is known, a segment's ramps may use what its curvature (on
  // an arc, at its junctions) leaves over where the path is straight: its axes need no share
  // for centripetal acceleration there.
  void close(Entry& e, double exitLimit, double exitRadius) const {
    if (machine_.jerkLimited()) return;  // the jerk filter was sized for the fixed share
    const double most = budget_.tangentialAccelWithoutJerkLimit;
    auto junctionCentripetal = [](double speed, double r) {
      return std::isfinite(r) && r > 0 ? speed * speed / r : 0.0;
    };
    const double normal = std::max({e.centripetal, junctionCentripetal(e.planned.entryLimit, e.entryRadius),
                                    junctionCentripetal(exitLimit, exitRadius)});
    const double available = e.axisAccel * (1.0 - budget_.cornerAccel) - normal;
    e.planned.accel = std::min(std::clamp(available, e.planned.accel, most * e.axisAccel), e.accelCap);
  }

  // After a forced commit: the forward pass again from the speed committed at the window's
  // start, so that no segment speeds up beyond its ramps from there.
  void redoForward(double startSpeed) {
    window_[head_].entryForward = startSpeed;
    for (std::size_t k = head_ + 1; k < window_.size(); ++k) {
      const Entry& before = window_[k - 1];
      window_[k].entryForward = std::min(window_[k].planned.entryLimit,
                                         std::sqrt(before.entryForward * before.entryForward +
                                                   2.0 * before.planned.accel * before.planned.length));
    }
  }

  const Machine& machine_;
  const LimitBudget budget_;
  const std::string source_;
  const GenericLimits limits_;
  double holdBefore_ = 0;  // s of dwell before the first motion
  bool stopped_ = false;   // a stop is already planned at the current junction
  bool finished_ = false;
  std::uint64_t segments_ = 0;        // segments added
  std::uint64_t closedSegments_ = 0;  // segments closed
  std::size_t forcedCommits_ = 0;
  PathSegment previous_;              // the last segment added (whole, before blends shortened it)
  Vec3 previousEndTangent_ = Vec3::Zero();  // the path's direction where it ends
  bool previousCurve_ = false;        // it is run as a chord curve
  bool previousRapid_ = false;
  // The generic control runs chords as curves where the machine's jerk is limited (without a
  // jerk limit, corner blends hold the feed on chords: corner_blend.h).
  const bool smoothsChords_ = machine_.control.chordSmoothing && machine_.jerkLimited();
  ChordRun run_{0.5 * limits_.smoothingTolerance()};
  PathSegment lastChord_;              // the last chord pushed into the run
  std::vector<FittedChord> fitted_;    // planSettledChords()'s, kept for its room
  // The junction after the last segment added (before the first: the start), until the next
  // segment is added: its speed limit and, between lines, its three-point radius (mm).
  double junctionLimit_ = 0.0;        // the machine starts at rest
  double junctionRadius_ = kInfinity;
  // window_[head_, closed_) are closed, window_[closed_] (unless finished) is the last added.
  std::vector<Entry> window_;
  std::size_t head_ = 0, closed_ = 0;
  std::vector<double> speeds_;        // commit()'s junction speeds, from window_[head_]
};

}  // namespace

double PlannedSegment::cruiseTime() const {
  if (peakSpeed <= 0) return 0;
  const double rest = length - accelDistance() - decelDistance();
  return rest > 0 ? rest / peakSpeed : 0;
}

double FeedPlan::profileDuration() const {
  double t = holdBefore;
  for (const PlannedSegment& s : segments) t += s.motionTime() + s.holdAfter;
  return t;
}

FeedPlan planFeed(const Program& program, const Machine& machine, const LimitBudget& budget,
                  const ProgressCallback& progress) {
  Planner planner(machine, budget, program.source);
  FeedPlan plan;
  plan.filterTime1 = planner.filterTime1();
  plan.filterTime2 = planner.filterTime2();
  plan.cycle = machine.cycle;
  plan.segments.reserve(program.moves.size());
  const std::size_t n = program.moves.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (progress && (i & 0xFFFF) == 0) progress(0.5 * static_cast<double>(i) / n);
    planner.add(static_cast<std::uint32_t>(i), program.moves[i], program.startOf(i));
  }
  planner.finish();
  planner.commit(plan.segments);
  plan.holdBefore = planner.holdBefore();
  if (progress) progress(1.0);
  return plan;
}

struct StreamingFeedPlanner::Impl {
  Impl(const Machine& machine, const LimitBudget& budget, std::string source)
      : planner(machine, budget, std::move(source)) {}
  Planner planner;
  std::size_t commitEvery = 0, maxHeld = 0;
  std::uint64_t closedAtLastCommit = 0;
  std::size_t largestHeld = 0;
};

StreamingFeedPlanner::StreamingFeedPlanner(const Machine& machine, const LimitBudget& budget, std::string source,
                                           const Window& window)
    : impl_(std::make_unique<Impl>(machine, budget, std::move(source))) {
  impl_->commitEvery = std::max<std::size_t>(window.commitEvery, 1);
  impl_->maxHeld = std::max(window.maxHeld, impl_->commitEvery);
}

StreamingFeedPlanner::~StreamingFeedPlanner() = default;

void StreamingFeedPlanner::add(std::uint32_t index, const Move& move, const Vec3& start) {
  impl_->planner.add(index, move, start);
  impl_->largestHeld = std::max(impl_->largestHeld, impl_->planner.held());
}

void StreamingFeedPlanner::finish() { impl_->planner.finish(); }

void StreamingFeedPlanner::take(std::vector<PlannedSegment>& out) {
  Planner& planner = impl_->planner;
  // A commit walks the whole window: attempted every commitEvery segments, the work per
  // segment stays constant.
  if (!planner.finished() && planner.closedSegments() - impl_->closedAtLastCommit < impl_->commitEvery) return;
  impl_->closedAtLastCommit = planner.closedSegments();
  planner.commit(out, impl_->maxHeld);
}

double StreamingFeedPlanner::holdBefore() const { return impl_->planner.holdBefore(); }
double StreamingFeedPlanner::filterTime1() const { return impl_->planner.filterTime1(); }
double StreamingFeedPlanner::filterTime2() const { return impl_->planner.filterTime2(); }
std::size_t StreamingFeedPlanner::held() const { return impl_->planner.held(); }
std::size_t StreamingFeedPlanner::largestHeld() const { return impl_->largestHeld; }
std::size_t StreamingFeedPlanner::forcedCommits() const { return impl_->planner.forcedCommits(); }

}  // namespace isurface
