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

#include <fmt/format.h>

namespace isurface {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// No curve's own limit is lower than this (mm/s): degenerate geometry (a 1e-9 mm arc) must
// still be passed in finite time, not skipped. Programmed feeds have no floor.
constexpr double kSlowestSpeed = 0.1;
// A single move or dwell longer than this (s) is a mistake in the program, not machining: it
// would make billions of samples.
constexpr double kLongestMove = 24 * 3600.0;

std::string speedName(float feedMmMin) {
  return feedMmMin < 0 ? std::string("at the machine's rapid speed") : fmt::format("at F{:g}", feedMmMin);
}

// Odd number of cycles closest to a filter time, at least 1.
int filterTaps(double time, double cycle) {
  const int half = static_cast<int>(std::lround(time / (2.0 * cycle)));
  return 2 * std::max(half, 0) + 1;
}

struct FilterTimes {
  double t1 = 0, t2 = 0;
};

FilterTimes chooseFilters(const Machine& machine, const LimitBudget& budget) {
  FilterTimes f;
  if (machine.jerkLimited()) {
    // A ramp of acceleration a, averaged over T1, changes acceleration at 2a/T1 at most (from
    // +a to -a): with the tangential shares of acceleration and jerk, T1 is the rise time a/j
    // scaled by 2 a-share / j-share. The rise time is the control's setting, lengthened where the
    // axes' own a/j is longer: a lower acceleration leaves T1 as it is, a lower jerk lengthens it.
    const double rise = std::max(machine.control.accelerationRiseTime, largestRiseTime(machine));
    f.t1 = 2.0 * budget.tangentialAccel / budget.tangentialJerk * rise;
  }
  // The corner filter spreads a corner's velocity step; a few cycles at least even without a
  // jerk limit, so that a corner is not a one-cycle acceleration spike.
  f.t2 = std::max(0.25 * f.t1, 5.0 * machine.cycle);
  const int n1 = filterTaps(f.t1, machine.cycle), n2 = filterTaps(f.t2, machine.cycle);
  f.t1 = n1 > 1 ? n1 * machine.cycle : 0;
  f.t2 = n2 * machine.cycle;
  return f;
}

double minAcceleration(const Machine& m) {
  return std::min({m.axes[0].maxAcceleration, m.axes[1].maxAcceleration, m.axes[2].maxAcceleration});
}
double minJerk(const Machine& m) {
  return std::min({m.axes[0].maxJerk, m.axes[1].maxJerk, m.axes[2].maxJerk});
}

// Largest speed at which a direction (unit or not) keeps every axis within `perAxis(i)`.
template <typename PerAxis>
double projectedLimit(const Vec3& direction, PerAxis perAxis) {
  double limit = kInfinity;
  for (int i = 0; i < 3; ++i) {
    const double c = std::abs(direction[i]);
    if (c > kRatioEpsilon) limit = std::min(limit, perAxis(i) / c);
  }
  return limit;
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
      : machine_(machine), budget_(budget), source_(std::move(source)) {
    const FilterTimes f = chooseFilters(machine, budget);
    t1_ = f.t1;
    t2_ = f.t2;
    smoothingTolerance_ = budget.cornerTolerance * machine.chordTolerance;
    settleTime_ = t1_ + t2_;
    for (int a = 0; a < 3; ++a) {
      const AxisLimits& axis = machine.axes[a];
      filterAccel_[a] = machine.jerkLimited() ? 0.5 * budget.tangentialJerk * axis.maxJerk * t1_
                                              : budget.tangentialAccel * axis.maxAcceleration;
      rampAccel_[a] = std::min(budget.tangentialAccel * axis.maxAcceleration, filterAccel_[a]);
    }
  }

  double filterTime1() const { return t1_; }
  double filterTime2() const { return t2_; }
  double holdBefore() const { return holdBefore_; }
  std::size_t held() const { return window_.size() - head_; }
  std::size_t forcedCommits() const { return forcedCommits_; }
  std::uint64_t closedSegments() const { return closedSegments_; }
  bool finished() const { return finished_; }

  // Move `index`, which starts at `start`.
  void add(std::uint32_t index, const Move& move, const Vec3& start) {
    if (move.kind == MoveKind::Dwell) {
      const double seconds = std::max(0.0, move.dwellSeconds());
      if (seconds > kLongestMove)
        throw InputError(Diagnostic{source_, move.line, move.column,
                                    fmt::format("a dwell of {:.4g} s is longer than {:.0f} h: not a real program",
                                                seconds, kLongestMove / 3600)});
      if (segments_ == 0) holdBefore_ += seconds;
      else window_.back().planned.holdAfter += seconds;
      stopAtJunction();
      return;
    }
    const PathSegment seg = PathSegment::from(start, move);
    if (seg.length > 0) {
      if (segments_ > 0) {
        double hold = 0;
        const double limit = junctionLimit(previous_, seg, window_.back().planned.accel, hold);
        if (limit > 0) junctionLimit_ = std::min(junctionLimit_, limit);
        else stopAtJunction(hold);
      }
      addSegment(index, move, seg);
      previous_ = seg;
    }
    if (move.flags & (kExactStop | kStopAfter)) stopAtJunction();
  }

  // The program has ended: the machine comes to rest after the last segment.
  void finish() {
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

  // The machine comes to rest at the current junction and waits `hold` seconds; by default
  // until the filters have drained, so that the corner is reached exactly (an exact stop, as
  // in-position checking does).
  void stopAtJunction(double hold = -1) {
    if (hold < 0) hold = settleTime_;
    junctionLimit_ = 0.0;
    if (segments_ > 0) {
      double& planned = window_.back().planned.holdAfter;
      planned = stopped_ ? std::max(planned, hold) : planned + hold;
    }
    stopped_ = true;
  }

  void addSegment(std::uint32_t index, const Move& move, const PathSegment& seg) {
    Entry e;
    PlannedSegment& ps = e.planned;
    ps.move = index;
    ps.length = seg.length;
    double speed = move.kind == MoveKind::Rapid
                       ? machine_.rapidVelocity
                       : mmPerMinToMmPerS(static_cast<double>(move.feed));
    if (seg.arc) {
      const ArcGeometry& g = seg.arcGeometry;
      const auto& ax = machine_.axes;
      // Both plane axes reach the full tangential speed somewhere on the arc.
      const double planeVelocity = std::min(ax[g.axes.u].maxVelocity, ax[g.axes.v].maxVelocity);
      const double planeAccel = std::min(ax[g.axes.u].maxAcceleration, ax[g.axes.v].maxAcceleration);
      const double pitch = seg.length > 0 ? std::abs(g.endW - g.startW) / seg.length : 0;
      speed = std::min(speed, planeVelocity);
      if (pitch > kRatioEpsilon) speed = std::min(speed, ax[g.axes.w].maxVelocity / pitch);
      speed = std::min(speed, curvatureLimit(g.minRadius(), planeAccel,
                                              std::min(filterAccel_[g.axes.u], filterAccel_[g.axes.v]), true));
    } else {
      speed = std::min(speed, projectedLimit(seg.direction, [&](int a) { return machine_.axes[a].maxVelocity; }));
    }
    // The feed and the axes' speeds are honoured however slow; only a curve's own limits have a
    // floor (kSlowestSpeed), so that degenerate geometry is still passed in finite time.
    if (!(speed > 0))
      throw InputError(Diagnostic{source_, move.line, move.column,
                                  move.kind == MoveKind::Rapid ? "the machine's rapid speed is not above 0"
                                                               : fmt::format("feed F{:g} is not above 0", move.feed)});
    ps.peakSpeed = speed;  // the cap until commit() settles the profile
    ps.cap = speed;
    ps.accel = tangentialAccel(seg);
    e.axisAccel = ps.accel / budget_.tangentialAccel;
    e.accelCap = seg.arc ? curveAccelLimit(seg.arcGeometry.minRadius()) : kInfinity;
    ps.accel = std::min(ps.accel, e.accelCap);
    e.centripetal = seg.arc ? speed * speed / std::max(seg.arcGeometry.minRadius(), kLengthEpsilon) : 0.0;
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

  // The acceleration along the path that keeps every axis within its share, mm/s^2.
  double tangentialAccel(const PathSegment& seg) const {
    if (!seg.arc) return projectedLimit(seg.direction, [&](int a) { return rampAccel_[a]; });
    const ArcGeometry& g = seg.arcGeometry;
    double accel = std::min(rampAccel_[g.axes.u], rampAccel_[g.axes.v]);
    const double pitch = seg.length > 0 ? std::abs(g.endW - g.startW) / seg.length : 0;
    if (pitch > kRatioEpsilon) accel = std::min(accel, rampAccel_[g.axes.w] / pitch);
    return accel;
  }

  // Speed limit on a curve of radius r (mm): centripetal acceleration and its turning rate,
  // the deviation the filters cause on a curve, and (arcs) the chord error between samples.
  // `accel`: the axes' acceleration in the curve's plane; `rampBound`: the most its ramps may use
  // (filterAccel_). `onArc`: an exact arc, whose ramps addSegment holds within curveAccelLimit;
  // else the radius through three points of short G1 moves.
  double curvatureLimit(double radius, double accel, double rampBound, bool onArc) const {
    if (!(radius > kLengthEpsilon)) return kSlowestSpeed;
    if (!std::isfinite(radius)) return kInfinity;
    double v = std::sqrt(budget_.normalAccel * accel * radius);
    if (machine_.jerkLimited()) v = std::min(v, std::cbrt(budget_.normalJerk * minJerk(machine_) * radius * radius));
    // A curve of radius r traversed at v with tangential acceleration a, averaged over the
    // filters (S = U1 + U2, U uniform over T1 and T2), falls inside by
    // E[(v S + a S^2 / 2)^2] / (2 r) = (v^2 E[S^2] + a^2 E[S^4] / 4) / (2 r).
    // On an arc the ramps are held within curveAccelLimit (addSegment), so that at least half
    // the tolerance is left for the speed: an arc of 0.3 mm is passed at a few hundred mm/min,
    // not at a crawl.
    const double s2 = (t1_ * t1_ + t2_ * t2_) / 12.0;
    if (s2 > 0) {
      const double a = std::min(rampBound, onArc ? curveAccelLimit(radius) : kInfinity);
      const double room = 2.0 * radius * smoothingTolerance_ - a * a * filterMoment4() / 4.0;
      v = std::min(v, room > 0 ? std::sqrt(room / s2) : kSlowestSpeed);
    }
    const double e = machine_.chordTolerance;
    if (onArc && 2.0 * radius > e)
      v = std::min(v, 2.0 * std::sqrt(2.0 * radius * e - e * e) / machine_.cycle);
    return v;
  }

  // E[S^4] of the filters' combined delay S = U1 + U2 (U uniform over T1 and T2), s^4.
  double filterMoment4() const {
    return std::pow(t1_, 4) / 80.0 + std::pow(t2_, 4) / 80.0 + t1_ * t1_ * t2_ * t2_ / 24.0;
  }

  // The tangential acceleration (mm/s^2) on a curve of radius r (mm) whose share of the filters'
  // deviation, a^2 E[S^4] / 4, is at most half the smoothing tolerance's 2 r tol.
  double curveAccelLimit(double radius) const {
    const double s4 = filterMoment4();
    return s4 > 0 && radius > 0 ? 2.0 * std::sqrt(radius * smoothingTolerance_ / s4) : kInfinity;
  }

  // 0 means the corner is too sharp to pass in motion: stop there for `hold` seconds.
  double junctionLimit(const PathSegment& in, const PathSegment& out, double accelIn, double& hold) {
    const Vec3 turn = out.startTangent() - in.endTangent();
    const double turnNorm = turn.norm();
    double v = kInfinity;
    if (turnNorm > kRoundingSlack) {
      // The velocity step v*|turn| at the corner, averaged by the filters, must fit the
      // corner's share of acceleration and jerk, and the rounding must stay in tolerance.
      const double spreadTime = std::max(t1_, t2_);
      v = std::min(v, projectedLimit(turn, [&](int a) {
                     return budget_.cornerAccel * machine_.axes[a].maxAcceleration * spreadTime;
                   }));
      if (machine_.jerkLimited() && t1_ > 0)
        v = std::min(v, projectedLimit(turn, [&](int a) {
                       return budget_.cornerJerk * machine_.axes[a].maxJerk * t1_ * t2_;
                     }));
      // Averaged over the filters, the samples around a corner passed at v with tangential
      // acceleration up to a lie off the path by about
      //   |turn| / 2 * (v (T1 + T2) / 4 + a (T1^2 + T2^2) / 24).
      const double accel =
          machine_.jerkLimited()
              ? std::max(projectedLimit(in.endTangent(), [&](int a) { return filterAccel_[a]; }),
                         projectedLimit(out.startTangent(), [&](int a) { return filterAccel_[a]; }))
              : std::max(accelIn, tangentialAccel(out));
      const double budget = 2.0 * smoothingTolerance_ / turnNorm - accel * (t1_ * t1_ + t2_ * t2_) / 24.0;
      if (budget <= 0) {
        // Stopped at the corner for h, the filters (width W = T1 + T2, taken as uniform, which
        // overstates their tails) still mix in both legs where the ramps leave and join it:
        // the samples fall off the corner by about sin(angle) a (W - h)^3 / (48 W).
        const double width = t1_ + t2_;
        const double sine = turnNorm * std::sqrt(std::max(0.0, 1.0 - 0.25 * turnNorm * turnNorm));
        const double reach = sine > kRatioEpsilon ? std::cbrt(48.0 * width * smoothingTolerance_ / (accel * sine)) : width;
        hold = std::clamp(width - reach, 0.0, width);
        return 0.0;
      }
      v = std::min(v, 4.0 * budget / (t1_ + t2_));
    }
    if (!in.arc && !out.arc) {
      // Short G1 moves approximate a curve: its radius from three points limits the speed.
      const double radius = threePointRadius(in.start, in.end, out.end);
      junctionRadius_ = radius;
      v = std::min(v, curvatureLimit(radius, minAcceleration(machine_), filterAccel_.minCoeff(), false));
    }
    return v;
  }

  const Machine& machine_;
  const LimitBudget budget_;
  const std::string source_;
  double t1_ = 0, t2_ = 0;
  // mm/s^2 per axis: the most a ramp may use with the jerk filter T1 (the tangential share of
  // jerk over T1 / 2; without a jerk limit, the tangential share of acceleration), which bounds
  // the filters' deviation whatever the acceleration limits are; and what ramps use (also within
  // the tangential share of acceleration).
  Vec3 filterAccel_ = Vec3::Zero(), rampAccel_ = Vec3::Zero();
  double settleTime_ = 0;  // s for the filters to drain
  double smoothingTolerance_ = 0;
  double holdBefore_ = 0;  // s of dwell before the first motion
  bool stopped_ = false;   // a stop is already planned at the current junction
  bool finished_ = false;
  std::uint64_t segments_ = 0;        // segments added
  std::uint64_t closedSegments_ = 0;  // segments closed
  std::size_t forcedCommits_ = 0;
  PathSegment previous_;              // the last segment added
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
