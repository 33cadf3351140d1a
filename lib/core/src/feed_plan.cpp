#include "isurface/core/feed_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "isurface/core/diagnostic.h"
#include "isurface/core/path_segment.h"

#include <fmt/format.h>

namespace isurface {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// No segment is planned slower than this (mm/s): degenerate geometry (a 1e-9 mm arc) must
// still be passed in finite time, not skipped.
constexpr double kSlowestSpeed = 0.1;
// A single move or dwell longer than this (s) is a mistake in the program, not machining: it
// would make billions of samples.
constexpr double kLongestMove = 24 * 3600.0;

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
    // +a to -a): T1 = 2 a / j keeps the tangential jerk within its share on every axis.
    for (const AxisLimits& axis : machine.axes)
      f.t1 = std::max(f.t1, 2.0 * budget.tangentialAccel * axis.maxAcceleration /
                                (budget.tangentialJerk * axis.maxJerk));
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
    if (c > 1e-12) limit = std::min(limit, perAxis(i) / c);
  }
  return limit;
}

class Planner {
 public:
  Planner(const Program& program, const Machine& machine, const LimitBudget& budget)
      : program_(program), machine_(machine), budget_(budget) {
    const FilterTimes f = chooseFilters(machine, budget);
    t1_ = f.t1;
    t2_ = f.t2;
    smoothingTolerance_ = budget.cornerTolerance * machine.chordTolerance;
    settleTime_ = t1_ + t2_;
  }

  FeedPlan run(const ProgressCallback& progress) {
    FeedPlan plan;
    plan.filterTime1 = t1_;
    plan.filterTime2 = t2_;
    plan.cycle = machine_.cycle;
    plan.segments.reserve(program_.moves.size());
    junction_.reserve(program_.moves.size() + 1);
    junction_.push_back(0.0);  // the machine starts at rest
    junctionRadius_.push_back(kInfinity);
    maxSpeed_.reserve(program_.moves.size());

    PathSegment previous;
    bool havePrevious = false;
    const std::size_t n = program_.moves.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (progress && (i & 0xFFFF) == 0) progress(0.5 * static_cast<double>(i) / n);
      const Move& move = program_.moves[i];
      if (move.kind == MoveKind::Dwell) {
        const double seconds = std::max(0.0, move.dwellSeconds());
        if (seconds > kLongestMove)
          throw InputError(Diagnostic{program_.source, move.line, 0,
                                      fmt::format("a dwell of {:.0f} s is longer than {:.0f} h: not a real program",
                                                  seconds, kLongestMove / 3600)});
        if (plan.segments.empty()) plan.holdBefore += seconds;
        else plan.segments.back().holdAfter += seconds;
        stopAtJunction(plan);
        continue;
      }
      const PathSegment seg = PathSegment::from(program_, i);
      if (seg.length > 0) {
        if (havePrevious) {
          double hold = 0;
          const double limit = junctionLimit(previous, seg, plan.segments.back().accel, hold);
          if (limit > 0) junction_.back() = std::min(junction_.back(), limit);
          else stopAtJunction(plan, hold);
        }
        addSegment(plan, static_cast<std::uint32_t>(i), move, seg);
        previous = seg;
        havePrevious = true;
      }
      if (move.flags & (kExactStop | kStopAfter)) stopAtJunction(plan);
    }
    junction_.back() = 0.0;  // and ends at rest
    solveSpeeds(plan);
    for (const PlannedSegment& segment : plan.segments)
      if (segment.motionTime() > kLongestMove) {
        const Move& move = program_.moves[segment.move];
        throw InputError(Diagnostic{program_.source, move.line, 0,
                                    fmt::format("this move takes {:.0f} h at F{:g}: an impossible feed for {:.1f} mm",
                                                segment.motionTime() / 3600, move.feed, segment.length)});
      }
    if (progress) progress(1.0);
    return plan;
  }

 private:
  // The machine comes to rest at the current junction and waits `hold` seconds; by default
  // until the filters have drained, so that the corner is reached exactly (an exact stop, as
  // in-position checking does).
  void stopAtJunction(FeedPlan& plan, double hold = -1) {
    if (hold < 0) hold = settleTime_;
    junction_.back() = 0.0;
    if (!plan.segments.empty()) {
      double& planned = plan.segments.back().holdAfter;
      planned = stopped_ ? std::max(planned, hold) : planned + hold;
    }
    stopped_ = true;
  }

  void addSegment(FeedPlan& plan, std::uint32_t index, const Move& move, const PathSegment& seg) {
    PlannedSegment ps;
    ps.move = index;
    ps.length = seg.length;
    double speed = move.kind == MoveKind::Rapid
                       ? machine_.rapidVelocity
                       : std::max(static_cast<double>(move.feed), 1.0) / 60.0;
    if (seg.arc) {
      const ArcGeometry& g = seg.arcGeometry;
      const auto& ax = machine_.axes;
      // Both plane axes reach the full tangential speed somewhere on the arc.
      const double planeVelocity = std::min(ax[g.axes.u].maxVelocity, ax[g.axes.v].maxVelocity);
      const double planeAccel = std::min(ax[g.axes.u].maxAcceleration, ax[g.axes.v].maxAcceleration);
      const double pitch = seg.length > 0 ? std::abs(g.endW - g.startW) / seg.length : 0;
      speed = std::min(speed, planeVelocity);
      if (pitch > 1e-12) speed = std::min(speed, ax[g.axes.w].maxVelocity / pitch);
      speed = std::min(speed, curvatureLimit(g.minRadius(), planeAccel, true));
    } else {
      speed = std::min(speed, projectedLimit(seg.direction, [&](int a) { return machine_.axes[a].maxVelocity; }));
    }
    speed = std::max(speed, kSlowestSpeed);
    ps.peakSpeed = speed;  // the cap until solveSpeeds() settles the profile
    ps.accel = tangentialAccel(seg);
    plan.segments.push_back(ps);
    maxSpeed_.push_back(speed);
    axisAccel_.push_back(ps.accel / budget_.tangentialAccel);
    centripetal_.push_back(seg.arc ? speed * speed / std::max(seg.arcGeometry.minRadius(), kLengthEpsilon) : 0.0);
    junction_.push_back(kInfinity);
    junctionRadius_.push_back(kInfinity);
    stopped_ = false;
  }

  // The acceleration along the path that keeps every axis within its share, mm/s^2.
  double tangentialAccel(const PathSegment& seg) const {
    const auto& ax = machine_.axes;
    if (!seg.arc)
      return budget_.tangentialAccel * projectedLimit(seg.direction, [&](int a) { return ax[a].maxAcceleration; });
    const ArcGeometry& g = seg.arcGeometry;
    double accel = std::min(ax[g.axes.u].maxAcceleration, ax[g.axes.v].maxAcceleration);
    const double pitch = seg.length > 0 ? std::abs(g.endW - g.startW) / seg.length : 0;
    if (pitch > 1e-12) accel = std::min(accel, ax[g.axes.w].maxAcceleration / pitch);
    return budget_.tangentialAccel * accel;
  }

  // Speed limit on a curve of radius r (mm): centripetal acceleration and its turning rate,
  // the deviation the filters cause on a curve, and (arcs) the chord error between samples.
  double curvatureLimit(double radius, double accel, bool chordBetweenSamples) const {
    if (!(radius > kLengthEpsilon)) return kSlowestSpeed;
    if (!std::isfinite(radius)) return kInfinity;
    double v = std::sqrt(budget_.normalAccel * accel * radius);
    if (machine_.jerkLimited()) v = std::min(v, std::cbrt(budget_.normalJerk * minJerk(machine_) * radius * radius));
    // A curve of radius r traversed at v with tangential acceleration a, averaged over the
    // filters (S = U1 + U2, U uniform over T1 and T2), falls inside by
    // E[(v S + a S^2 / 2)^2] / (2 r) = (v^2 E[S^2] + a^2 E[S^4] / 4) / (2 r).
    const double s2 = (t1_ * t1_ + t2_ * t2_) / 12.0;
    const double s4 = std::pow(t1_, 4) / 80.0 + std::pow(t2_, 4) / 80.0 + t1_ * t1_ * t2_ * t2_ / 24.0;
    if (s2 > 0) {
      const double a = budget_.tangentialAccel * accel;
      const double room = 2.0 * radius * smoothingTolerance_ - a * a * s4 / 4.0;
      v = std::min(v, room > 0 ? std::sqrt(room / s2) : kSlowestSpeed);
    }
    const double e = machine_.chordTolerance;
    if (chordBetweenSamples && 2.0 * radius > e)
      v = std::min(v, 2.0 * std::sqrt(2.0 * radius * e - e * e) / machine_.cycle);
    return v;
  }

  // 0 means the corner is too sharp to pass in motion: stop there for `hold` seconds.
  double junctionLimit(const PathSegment& in, const PathSegment& out, double accelIn, double& hold) {
    const Vec3 turn = out.startTangent() - in.endTangent();
    const double turnNorm = turn.norm();
    double v = kInfinity;
    if (turnNorm > 1e-9) {
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
      const double accel = std::max(accelIn, tangentialAccel(out));
      const double budget = 2.0 * smoothingTolerance_ / turnNorm - accel * (t1_ * t1_ + t2_ * t2_) / 24.0;
      if (budget <= 0) {
        // Stopped at the corner for h, the filters (width W = T1 + T2, taken as uniform, which
        // overstates their tails) still mix in both legs where the ramps leave and join it:
        // the samples fall off the corner by about sin(angle) a (W - h)^3 / (48 W).
        const double width = t1_ + t2_;
        const double sine = turnNorm * std::sqrt(std::max(0.0, 1.0 - 0.25 * turnNorm * turnNorm));
        const double reach = sine > 1e-12 ? std::cbrt(48.0 * width * smoothingTolerance_ / (accel * sine)) : width;
        hold = std::clamp(width - reach, 0.0, width);
        return 0.0;
      }
      v = std::min(v, 4.0 * budget / (t1_ + t2_));
    }
    if (!in.arc && !out.arc) {
      // Short G1 moves approximate a curve: its radius from three points limits the speed.
      const double radius = threePointRadius(in.start, in.end, out.end);
      junctionRadius_.back() = radius;
      v = std::min(v, curvatureLimit(radius, minAcceleration(machine_), false));
    }
    return v;
  }

  // Where the path is straight, its axes need no share for centripetal acceleration: a
  // segment's ramps may use what its curvature (on an arc, at its junctions) leaves over.
  void shareAcceleration(std::vector<PlannedSegment>& segs) const {
    if (machine_.jerkLimited()) return;  // the jerk filter was sized for the fixed share
    const double most = budget_.tangentialAccelWithoutJerkLimit;
    auto junctionCentripetal = [&](std::size_t j) {
      const double r = junctionRadius_[j];
      return std::isfinite(r) && r > 0 ? junction_[j] * junction_[j] / r : 0.0;
    };
    for (std::size_t k = 0; k < segs.size(); ++k) {
      const double normal = std::max({centripetal_[k], junctionCentripetal(k), junctionCentripetal(k + 1)});
      const double available = axisAccel_[k] * (1.0 - budget_.cornerAccel) - normal;
      segs[k].accel = std::clamp(available, segs[k].accel, most * axisAccel_[k]);
    }
  }

  void solveSpeeds(FeedPlan& plan) {
    auto& segs = plan.segments;
    const std::size_t n = segs.size();
    std::vector<double>& v = junction_;  // becomes the junction speeds
    for (std::size_t k = 1; k < n; ++k) v[k] = std::min({v[k], maxSpeed_[k - 1], maxSpeed_[k]});
    v[0] = 0.0;
    v[n] = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      segs[k].cap = maxSpeed_[k];
      segs[k].entryLimit = v[k];
    }
    shareAcceleration(segs);
    for (std::size_t k = 0; k < n; ++k)
      v[k + 1] = std::min(v[k + 1], std::sqrt(v[k] * v[k] + 2.0 * segs[k].accel * segs[k].length));
    for (std::size_t k = n; k-- > 0;)
      v[k] = std::min(v[k], std::sqrt(v[k + 1] * v[k + 1] + 2.0 * segs[k].accel * segs[k].length));
    for (std::size_t k = 0; k < n; ++k) {
      PlannedSegment& s = segs[k];
      s.entrySpeed = v[k];
      s.exitSpeed = v[k + 1];
      const double reachable =
          std::sqrt(s.accel * s.length + 0.5 * (s.entrySpeed * s.entrySpeed + s.exitSpeed * s.exitSpeed));
      s.peakSpeed = std::max({std::min(maxSpeed_[k], reachable), s.entrySpeed, s.exitSpeed});
    }
  }

  const Program& program_;
  const Machine& machine_;
  const LimitBudget budget_;
  double t1_ = 0, t2_ = 0;
  double settleTime_ = 0;  // s for the filters to drain
  bool stopped_ = false;   // a stop is already planned at the current junction
  double smoothingTolerance_ = 0;
  std::vector<double> junction_;  // speed limit at the start of segment k (k == size: the end)
  std::vector<double> maxSpeed_;
  std::vector<double> axisAccel_;       // mm/s^2 along segment k that its axes allow, no shares
  std::vector<double> centripetal_;     // mm/s^2 on arc k at its speed cap
  std::vector<double> junctionRadius_;  // mm, three-point radius at junction k between lines
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

double threePointRadius(const Vec3& previous, const Vec3& point, const Vec3& next) {
  const Vec3 a = next - point, b = point - previous, c = next - previous;
  const double cross = a.cross(b).norm();
  const double lengths = a.norm() * b.norm() * c.norm();
  if (!(cross > 1e-15 * lengths) || lengths == 0) return kInfinity;
  return lengths / (2.0 * cross);
}

FeedPlan planFeed(const Program& program, const Machine& machine, const LimitBudget& budget,
                  const ProgressCallback& progress) {
  return Planner(program, machine, budget).run(progress);
}

}  // namespace isurface
