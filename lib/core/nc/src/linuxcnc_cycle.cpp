#include "linuxcnc_cycle.h"

#include <algorithm>
#include <cmath>

#include "linuxcnc_blend.h"

namespace isurface::linuxcnc {

namespace {

constexpr double kVelocityEpsilon = 1e-8;  // mm/s
constexpr double kTimeEpsilon = 1e-12;     // s
constexpr double kRampCutoff = 1.0 / 100;  // s, ARC_BLEND_RAMP_FREQ = 100 Hz

// The speed that, decelerating at `a`, still ends at `vFinal` after `dx` mm (the trapezoid's
// discrete form, one cycle of `dt` ahead).
double trapezoidalDesiredVelocity(double a, double dx, double vFinal, double v, double dt) {
  dt = std::max(dt, kTimeEpsilon);
  const double half = a * dt * 0.5;
  const double discriminant = vFinal * vFinal + a * (2.0 * dx - v * dt) + half * half;
  double velocity = -half;
  if (discriminant > half * half) velocity += std::sqrt(discriminant);
  return velocity;
}

double saturate(double x, double limit) { return std::clamp(x, -limit, limit); }

struct Update {
  double acceleration;
  double desired;
};

Update trapezoid(const Segment& tc, const Segment* next) {
  const double target = realTargetVelocity(tc);
  const double finalVelocity = realFinalVelocity(tc, next);
  const double a = tangentialAcceleration(tc);
  const double desired = trapezoidalDesiredVelocity(a, tc.target - tc.progress, finalVelocity, tc.velocity, tc.cycle);
  const double velocity = saturate(desired, target);
  return {saturate((velocity - tc.velocity) / std::max(tc.cycle, kTimeEpsilon), a), desired};
}

// A short tangent segment: one constant acceleration from its speed now to its final speed.
bool ramp(const Segment& tc, const Segment* next, Update& out) {
  const double finalVelocity = realFinalVelocity(tc, next);
  if (finalVelocity < kVelocityEpsilon) return false;
  const double average = (tc.velocity + finalVelocity) / 2.0;
  const double dt = average > kVelocityEpsilon ? std::max((tc.target - tc.progress) / average, 1e-16) : 1e-16;
  out = {saturate((finalVelocity - tc.velocity) / dt, tangentialAcceleration(tc)), finalVelocity};
  return true;
}

// Whether the segment ends within the next cycle, and how long it then takes (checkEndCondition).
void checkEnd(Segment& tc, const Segment* next, double cycle) {
  const double remaining = tc.target - tc.progress;
  const double vFinal = realFinalVelocity(tc, next);
  const double aMax = tangentialAcceleration(tc);
  const double average = (tc.velocity + vFinal) / 2.0;
  double dt = kTimeEpsilon / 2.0;
  if (average > kVelocityEpsilon) dt = std::max(dt, remaining / average);
  else if (remaining > average * cycle && remaining > 1e-12) return;
  double a = std::clamp((vFinal - tc.velocity) / std::max(dt, kTimeEpsilon), -aMax, aMax);
  double endVelocity = vFinal;
  if (a != (vFinal - tc.velocity) / std::max(dt, kTimeEpsilon)) {
    const double discriminant = std::pow(tc.velocity / a, 2) + 2.0 / a * remaining;
    if (discriminant < 0) return;
    if (discriminant < kTimeEpsilon * kTimeEpsilon) dt = -tc.velocity / a;
    else if (a > 0) dt = -tc.velocity / a + std::sqrt(discriminant);
    else dt = -tc.velocity / a - std::sqrt(discriminant);
    endVelocity = tc.velocity + dt * a;
  }
  if (dt < cycle && !tc.splitting) {
    tc.splitting = true;
    tc.cycle = dt < kTimeEpsilon ? 0.0 : dt;
    tc.terminalVelocity = endVelocity;
  }
}

// One update of a segment over its `cycle`; moves the queue's position with it.
void updateCycle(MotionQueue& queue, Segment& tc, const Segment* next) {
  const Vec3 before = tc.pointAt(tc.progress);
  const Vec3 rotaryBefore = tc.rotaryAt(tc.progress);
  Update u{};
  if (!(tc.ramp && tc.term == Term::Tangent && ramp(tc, next, u))) u = trapezoid(tc, next);
  double v = tc.velocity + u.acceleration * tc.cycle;
  if (v < 0) {
    v = 0;
    if (tc.target - tc.progress < tc.velocity * tc.cycle) tc.progress = tc.target;
  } else {
    tc.progress = std::min(tc.progress + (v + tc.velocity) * 0.5 * tc.cycle, tc.target);
  }
  tc.velocity = v;
  tc.onFinalDeceleration = std::abs(u.desired - tc.velocity) < kVelocityEpsilon && u.acceleration < 0;
  checkEnd(tc, next, queue.cycle);
  queue.position += tc.pointAt(tc.progress) - before;
  queue.rotary += tc.rotaryAt(tc.progress) - rotaryBefore;
}

void activate(Segment& tc) {
  const double remaining = tc.target - tc.progress;
  const double time = 2.0 * remaining / (tc.velocity + std::min(tc.finalVelocity, realTargetVelocity(tc)));
  if (time < kRampCutoff && !tc.traverse && tc.term == Term::Tangent) tc.ramp = true;
  tc.active = true;
  tc.blendingNext = false;
  tc.onFinalDeceleration = false;
}

}  // namespace

double realTargetVelocity(const Segment& s) { return std::min(s.requested, maxTargetVelocity(s)); }

double realFinalVelocity(const Segment& s, const Segment* next) {
  if (s.term != Term::Tangent) return 0.0;
  const double target = std::min(realTargetVelocity(s), next ? realTargetVelocity(*next) : 0.0);
  return std::min(s.finalVelocity, target);
}

SegmentPart runCycle(MotionQueue& queue) {
  Segment& tc = queue.segments.front();
  Segment* next = queue.segments.size() > 1 ? &queue.segments[1] : nullptr;
  if (!tc.active) activate(tc);
  const Segment* reporting = &tc;
  if (tc.splitting) {
    // The segment ends within this cycle; a tangent or blending next one moves in the rest.
    const Vec3 before = tc.pointAt(tc.progress);
    const Vec3 rotaryBefore = tc.rotaryAt(tc.progress);
    tc.progress = tc.target;
    queue.position += tc.pointAt(tc.target) - before;
    queue.rotary += tc.rotaryAt(tc.target) - rotaryBefore;
    tc.remove = true;
    if (next && (tc.term == Term::Tangent || tc.term == Term::Parabolic)) {
      if (tc.term == Term::Tangent) {
        next->cycle = queue.cycle - tc.cycle;
        next->velocity = tc.terminalVelocity;
      }
      updateCycle(queue, *next, queue.segments.size() > 2 ? &queue.segments[2] : nullptr);
      if (!(tc.term == Term::Tangent && tc.cycle > next->cycle)) reporting = next;
    }
  } else {
    tc.cycle = queue.cycle;
    updateCycle(queue, tc, next);
    if (tc.term == Term::Parabolic && next) {
      double vThis = 0, vNext = 0;
      parabolicBlendVelocities(tc, *next, realTargetVelocity(tc), realTargetVelocity(*next), vThis, vNext, nullptr);
      tc.blendVelocity = vThis;
    }
    const bool blending = tc.term == Term::Parabolic && tc.onFinalDeceleration && tc.velocity < tc.blendVelocity;
    tc.blendingNext = tc.blendingNext || blending;
    if (next && tc.blendingNext) {
      // tpUpdateBlend sets the next segment's target_vel, which LinuxCNC 2.9 reads only for
      // spindle-synchronised moves (tcGetMaxTargetVel takes reqvel otherwise): the next segment
      // runs its own trapezoid, at its halved acceleration, from the start of the blend.
      updateCycle(queue, *next, nullptr);
      if (tc.velocity <= next->velocity) reporting = next;
    }
  }
  const SegmentPart part = reporting->part;
  if (tc.remove) queue.segments.pop_front();
  return part;
}

}  // namespace isurface::linuxcnc
