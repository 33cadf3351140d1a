#include "generic_limits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "isurface/base/geometry.h"
#include "isurface/base/tolerances.h"
#include "isurface/base/units.h"

namespace isurface {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// No curve's own limit is lower than this (mm/s): degenerate geometry (a 1e-9 mm arc) must
// still be passed in finite time, not skipped. Programmed feeds have no floor.
constexpr double kSlowestSpeed = 0.1;

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

// Largest speed at which every direction in the plane of unit normal `normal` keeps every axis
// within `perAxis(i)`: a direction in the plane has at most sqrt(1 - n_i^2) along axis i.
template <typename PerAxis>
double inPlaneLimit(const Vec3& normal, PerAxis perAxis) {
  double limit = kInfinity;
  for (int i = 0; i < 3; ++i) {
    const double c = std::sqrt(std::max(0.0, 1.0 - normal[i] * normal[i]));
    if (c > kRatioEpsilon) limit = std::min(limit, perAxis(i) / c);
  }
  return limit;
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

}  // namespace

GenericLimits::GenericLimits(const Machine& machine, const LimitBudget& budget) : machine_(machine), budget_(budget) {
  const FilterTimes f = chooseFilters(machine, budget);
  t1_ = f.t1;
  t2_ = f.t2;
  smoothingTolerance_ = budget.cornerTolerance * machine.chordTolerance;
  for (int a = 0; a < 3; ++a) {
    const AxisLimits& axis = machine.axes[a];
    filterAccel_[a] = machine.jerkLimited() ? 0.5 * budget.tangentialJerk * axis.maxJerk * t1_
                                            : budget.tangentialAccel * axis.maxAcceleration;
    rampAccel_[a] = std::min(budget.tangentialAccel * axis.maxAcceleration, filterAccel_[a]);
  }
}

double GenericLimits::segmentSpeed(const PathSegment& seg, const Move& move) const {
  double speed = move.kind == MoveKind::Rapid ? machine_.rapidVelocity : mmPerMinToMmPerS(static_cast<double>(move.feed));
  const auto& ax = machine_.axes;
  if (!seg.arc) return std::min(speed, projectedLimit(seg.direction, [&](int a) { return ax[a].maxVelocity; }));
  const ArcGeometry& g = seg.arcGeometry;
  // Both plane axes reach the full tangential speed somewhere on the arc.
  const double planeVelocity = std::min(ax[g.axes.u].maxVelocity, ax[g.axes.v].maxVelocity);
  const double planeAccel = std::min(ax[g.axes.u].maxAcceleration, ax[g.axes.v].maxAcceleration);
  const double pitch = seg.length > 0 ? std::abs(g.endW - g.startW) / seg.length : 0;
  speed = std::min(speed, planeVelocity);
  if (pitch > kRatioEpsilon) speed = std::min(speed, ax[g.axes.w].maxVelocity / pitch);
  return std::min(speed, curvatureLimit(g.minRadius(), planeAccel, std::min(filterAccel_[g.axes.u], filterAccel_[g.axes.v]),
                                        true, smoothingTolerance_));
}

double GenericLimits::chordCurveSpeed(const ChordSpline::Shape& curve, const Move& move) const {
  const auto& ax = machine_.axes;
  const double speed = std::min(mmPerMinToMmPerS(static_cast<double>(move.feed)),
                                projectedLimit(curve.largestDirection, [&](int a) { return ax[a].maxVelocity; }));
  const double radius = curve.largestCurvature > 0 ? 1.0 / curve.largestCurvature : kInfinity;
  return std::min(speed, curvatureLimit(radius, minAcceleration(machine_), filterAccel_.minCoeff(), true,
                                        smoothingTolerance_));
}

double GenericLimits::chordCurveAccel(const ChordSpline::Shape& curve) const {
  return projectedLimit(curve.largestDirection, [&](int a) { return rampAccel_[a]; });
}

double GenericLimits::blendAccel(const CornerBlend& blend) const {
  return inPlaneLimit(blend.normal(), [&](int a) { return rampAccel_[a]; });
}

double GenericLimits::tangentialAccel(const PathSegment& seg) const {
  if (!seg.arc) return projectedLimit(seg.direction, [&](int a) { return rampAccel_[a]; });
  const ArcGeometry& g = seg.arcGeometry;
  double accel = std::min(rampAccel_[g.axes.u], rampAccel_[g.axes.v]);
  const double pitch = seg.length > 0 ? std::abs(g.endW - g.startW) / seg.length : 0;
  if (pitch > kRatioEpsilon) accel = std::min(accel, rampAccel_[g.axes.w] / pitch);
  return accel;
}

double GenericLimits::curvatureLimit(double radius, double accel, double rampBound, bool onArc,
                                     double tolerance) const {
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
  const double s2 = filterMoment2();
  if (s2 > 0) {
    const double a = std::min(rampBound, onArc ? curveAccelLimit(radius, tolerance) : kInfinity);
    const double room = 2.0 * radius * tolerance - a * a * filterMoment4() / 4.0;
    v = std::min(v, room > 0 ? std::sqrt(room / s2) : kSlowestSpeed);
  }
  const double e = machine_.chordTolerance;
  if (onArc && 2.0 * radius > e)
    v = std::min(v, 2.0 * std::sqrt(2.0 * radius * e - e * e) / machine_.cycle);
  return v;
}

double GenericLimits::filterMoment4() const {
  return std::pow(t1_, 4) / 80.0 + std::pow(t2_, 4) / 80.0 + t1_ * t1_ * t2_ * t2_ / 24.0;
}

double GenericLimits::curveAccelLimit(double radius, double tolerance) const {
  const double s4 = filterMoment4();
  return s4 > 0 && radius > 0 ? 2.0 * std::sqrt(radius * tolerance / s4) : kInfinity;
}

double GenericLimits::cornerLimit(const PathSegment& in, const PathSegment& out, const Junction& junction,
                                  double accelIn, double& hold, double& radius) const {
  const Vec3 turn = junction.outTangent - junction.inTangent;
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
            ? std::max(projectedLimit(junction.inTangent, [&](int a) { return filterAccel_[a]; }),
                       projectedLimit(junction.outTangent, [&](int a) { return filterAccel_[a]; }))
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
  if (junction.betweenLines) {
    // Short G1 moves approximate a curve: its radius from three points limits the speed.
    radius = threePointRadius(in.start, in.end, out.end);
    v = std::min(v, curvatureLimit(radius, minAcceleration(machine_), filterAccel_.minCoeff(), false,
                                   smoothingTolerance_));
  }
  return v;
}

// The blend that may replace the corner where line `in` meets line `out` (move `move`): none at
// an arc or a sharp turn. The filters round a curve
// passed at its centripetal limit sqrt(k R) by k E[S^2] / 2, and the ramps on it as much again
// (curveAccelLimit): a larger share gains no speed, so the blend takes the rest. Where the
// filters need more, halves are fastest (the speed grows with the product of the two shares).
// A blend that reaches half a line's length takes no more than it needs.
BlendChoice GenericLimits::blendAt(const PathSegment& in, const PathSegment& out, const Move& move) const {
  BlendChoice c;
  // With a jerk limit, the jerk filter after interpolation rounds corners and curves itself (the
  // paper's model), and a blend's radius caps the speed along all of it: blending there was
  // slower on every program measured (docs/controls.md).
  if (machine_.jerkLimited()) return c;
  if (in.arc || out.arc) return c;
  const Vec3 normal = in.direction.cross(out.direction).normalized();
  const double planeAccel = inPlaneLimit(normal, [&](int a) { return machine_.axes[a].maxAcceleration; });
  const double filterNeed = budget_.normalAccel * planeAccel * filterMoment2();
  const double blendShare = smoothingTolerance_ - std::min(0.5 * smoothingTolerance_, filterNeed);
  // Each line gives at most half its length to the blend at either end.
  const double longest = 0.5 * std::min(in.length, out.length);
  c.reach = CornerBlend::reachFor(in.direction, out.direction, blendShare, longest);
  const std::optional<CornerBlend> blend = CornerBlend::at(out.start, in.direction, out.direction, c.reach);
  if (!blend) return BlendChoice{};
  c.filterTolerance = smoothingTolerance_ - std::min(blendShare, blend->deviation());
  c.speed = blendSpeed(*blend, move, c.filterTolerance);
  return c;
}

// The speed limit of a blend (mm/s): the feed, the axes' speeds in its plane, its curvature
// with the filters' rounding within `filterTolerance` (mm).
double GenericLimits::blendSpeed(const CornerBlend& blend, const Move& move, double filterTolerance) const {
  const Vec3 normal = blend.normal();
  const auto& ax = machine_.axes;
  const double planeAccel = inPlaneLimit(normal, [&](int a) { return ax[a].maxAcceleration; });
  const double rampBound = inPlaneLimit(normal, [&](int a) { return filterAccel_[a]; });
  const double speed = std::min(mmPerMinToMmPerS(static_cast<double>(move.feed)),
                                inPlaneLimit(normal, [&](int a) { return ax[a].maxVelocity; }));
  return std::min(speed, curvatureLimit(blend.radius(), planeAccel, rampBound, true, filterTolerance));
}

}  // namespace isurface
