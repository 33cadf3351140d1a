// LinuxCNC 2.9's motion: its canon's naive-CAM joining, its queue with blends and look-ahead
// (tpAddLine, tpAddCircle, tpRunOptimization), run cycle by cycle into samples.
#include "isurface/nc/linuxcnc_motion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/nc/run_bound.h"
#include "isurface/nc/servo.h"
#include "linuxcnc_arc_blend.h"
#include "linuxcnc_blend.h"
#include "linuxcnc_cycle.h"
#include "joint_limit_notes.h"
#include "linuxcnc_rotary.h"

namespace isurface {

using namespace linuxcnc;

namespace {

constexpr int kLookAheadDepth = 50;        // ARC_BLEND_OPTIMIZATION_DEPTH
constexpr int kPeaksBeforeStopping = 4;    // TP_OPTIMIZATION_CUTOFF
constexpr double kMinSegmentCycles = 1.02; // TP_MIN_SEGMENT_CYCLES
constexpr std::size_t kMostJoinedLines = 100;
// Segments queued ahead of the one moving: more than the look-ahead reaches, as on a control
// whose task reads the program far ahead of the motion.
constexpr std::size_t kQueueAhead = 4 * kLookAheadDepth;
constexpr std::size_t kBatch = 4096;
constexpr std::size_t kStalledCycles = 100000;

const char* const kRotaryNames = "ABC";

struct ChainPoint {
  Vec3 end;
  SegmentPart part;
};

}  // namespace

struct LinuxCncMotion::Impl {
  Impl(const Machine& m, const Vec3& start, SampleSink& s)
      : machine(m), sink(s), rotaryAxes(rotaryLimits(m)), canonEnd(start), startPosition(start) {
    queue.position = start;
    queue.cycle = m.cycle;
    for (int i = 0; i < 3; ++i) {
      bounds.velocity[i] = m.axes[i].maxVelocity;
      bounds.acceleration[i] = m.axes[i].maxAcceleration;
    }
    bounds.cycle = m.cycle;
    // On a five-axis machine the servos move the joints; at the start every rotary axis is at 0.
    const Vec3 joints = m.kinematics && m.kinematics->toolCentrePoint ? jointsFor(*m.kinematics, TipPose{start, {0, 0}}).linear : start;
    if (sink.wantsFeedback())
      for (int i = 0; i < 3; ++i) servos.emplace_back(m.axes[i], m.cycle, joints[i]);
    if (m.kinematics) jointLimits.emplace(m);
  }

  const Machine& machine;
  SampleSink& sink;
  AxisBounds bounds{};
  MotionQueue queue;
  std::vector<AxisServo> servos;
  std::vector<SimSample> batch;
  std::vector<JointSample> jointBatch;
  std::optional<JointLimitNotes> jointLimits;
  RotaryLimits rotaryAxes;
  InterpolationSummary summary;
  Vec3 canonEnd;  // where the next segment starts, mm
  Vec3 canonRotary = Vec3::Zero();  // A B C there, deg
  Vec3 startPosition;
  std::vector<ChainPoint> chain;
  PathBlending blending;
  std::deque<PathBlending> pendingBlending;
  double pathLength = 0;
  std::size_t segments = 0;
  SegmentPart lastPart{};

  void add(std::uint64_t index, const Move& move, const Vec3& start, const Vec3& rotaryEnd);
  Vec3 reachedRotary(const Move& move, const Vec3& programmed) const;
  void joinOrFlush(const Move& move, const SegmentPart& part);
  bool joinable(const Move& move) const;
  void flushChain();
  void enqueueLine(Vec3 from, Vec3 to, const Vec3& rotaryTo, bool traverse, std::uint8_t flags,
                   const SegmentPart& part);
  void enqueueArc(const Vec3& start, const Move& move, const Vec3& rotaryTo, const SegmentPart& part);
  void enqueue(Segment tc, std::uint8_t flags);
  void joinToPrevious(Segment& tc);
  bool insertBlend(Segment* prev, Segment& tc, BlendArc& blend);
  void finalize(Segment& s) const;
  void optimize();
  void runAhead(std::size_t keep);
  void emit(const SegmentPart& part);
  void push(const Vec3& position, const Vec3& rotary, const SegmentPart& part);
  void hold(double seconds);
  void flushBatch();
};

// Where the rotary axes go for a programmed A B C: a wrapping axis the shortest way; an axis
// past its range, or one the machine lacks, is refused with the move's line.
Vec3 LinuxCncMotion::Impl::reachedRotary(const Move& move, const Vec3& programmed) const {
  Vec3 reached = programmed;
  for (int i = 0; i < 3; ++i) {
    const auto u = static_cast<std::size_t>(i);
    if (programmed[i] == canonRotary[i]) continue;
    if (!rotaryAxes.present[u])
      throw InputError(Diagnostic{"", move.line, move.column,
                                  fmt::format("{} moves to {:g} deg, and the machine has no {} axis", kRotaryNames[i],
                                              programmed[i], kRotaryNames[i])});
    const RotaryAxis& axis = machine.kinematics->rotary[static_cast<std::size_t>(rotaryAxes.kinematicsIndex[u])];
    if (axis.wraps) {
      reached[i] = shortestWay(canonRotary[i], programmed[i]);
    } else if (programmed[i] < axis.minimum - 1e-9 || programmed[i] > axis.maximum + 1e-9) {
      throw InputError(Diagnostic{"", move.line, move.column,
                                  fmt::format("{} {:g} deg is past the machine's range of {} ({:g} to {:g} deg)",
                                              kRotaryNames[i], programmed[i], kRotaryNames[i], axis.minimum,
                                              axis.maximum)});
    }
  }
  return reached;
}

void LinuxCncMotion::Impl::add(std::uint64_t index, const Move& move, const Vec3& start, const Vec3& programmedRotary) {
  while (!pendingBlending.empty() && pendingBlending.front().firstMove <= index) {
    blending = pendingBlending.front();
    pendingBlending.pop_front();
  }
  const SegmentPart part{static_cast<std::uint32_t>(index), move.line, move.feed};
  const Vec3 rotaryEnd = move.isMotion() ? reachedRotary(move, programmedRotary) : canonRotary;
  const bool turns = rotaryEnd != canonRotary;
  if (move.kind == MoveKind::Dwell) {
    flushChain();
    runAhead(0);
    lastPart = part;
    hold(move.dwellSeconds());
    return;
  }
  if (move.isArc()) {
    flushChain();
    enqueueArc(start, move, rotaryEnd, part);
  } else if ((move.end - start).norm() < 1e-12 && !turns) {
    // A move of no length: nothing queued; a stop it asks for still holds.
  } else if (move.kind == MoveKind::Linear && !(move.flags & kExactStop) && blending.merge > 0 && !turns) {
    joinOrFlush(move, part);
  } else {
    // A move that turns a rotary axis is never joined (the canon's see_segment).
    flushChain();
    enqueueLine(start, move.end, rotaryEnd, move.kind == MoveKind::Rapid, move.flags, part);
  }
  // A program stop, tool or spindle change waits until the motion queued is done: the last
  // segment ends as it would end the program (at its own acceleration).
  if (move.flags & kStopAfter) {
    flushChain();
    runAhead(0);
  }
  runAhead(kQueueAhead);
}

bool LinuxCncMotion::Impl::joinable(const Move& move) const {
  if (chain.empty()) return true;
  if (chain.size() > kMostJoinedLines || chain.front().part.feed != move.feed) return false;
  for (const ChainPoint& p : chain)
    if (distanceToSegment(p.end, canonEnd, move.end) > blending.merge) return false;
  return true;
}

void LinuxCncMotion::Impl::joinOrFlush(const Move& move, const SegmentPart& part) {
  if (!joinable(move)) flushChain();
  chain.push_back({move.end, part});
}

// The joined lines become one segment, reported (as LinuxCNC reports it) under the last line.
void LinuxCncMotion::Impl::flushChain() {
  if (chain.empty()) return;
  const Vec3 to = chain.back().end;
  const SegmentPart last = chain.back().part;
  chain.clear();
  enqueueLine(canonEnd, to, canonRotary, false, 0, last);
}

void LinuxCncMotion::Impl::enqueueLine(Vec3 from, Vec3 to, const Vec3& rotaryTo, bool traverse, std::uint8_t flags,
                                       const SegmentPart& part) {
  Segment tc;
  tc.shape = Shape::Line;
  tc.start = from;
  tc.end = to;
  tc.rotaryStart = canonRotary;
  tc.rotaryEnd = rotaryTo;
  const StraightLimits limits = straightLimits(machine, rotaryAxes, to - from, rotaryTo - canonRotary);
  tc.target = limits.length;
  canonEnd = to;
  canonRotary = rotaryTo;
  if (tc.target < 1e-12) return;
  // A turn of the rotary axes alone keeps LinuxCNC's direction of a line of no length (+X).
  tc.direction = limits.linear ? Vec3((to - from).normalized()) : Vec3::UnitX();
  tc.traverse = traverse;
  // The machine's rapid rate bounds the tip, not a turn of the rotary axes alone.
  tc.maxVelocity = traverse && limits.linear ? std::min(limits.velocity, machine.rapidVelocity) : limits.velocity;
  tc.requested = traverse ? tc.maxVelocity : part.feed / 60.0;
  tc.maxAcceleration = limits.acceleration;
  tc.part = part;
  enqueue(std::move(tc), flags);
}

void LinuxCncMotion::Impl::enqueueArc(const Vec3& start, const Move& move, const Vec3& rotaryTo,
                                      const SegmentPart& part) {
  Segment tc;
  tc.shape = Shape::Arc;
  tc.arc = ArcGeometry::from(start, move);
  tc.start = start;
  tc.end = move.end;
  tc.target = tc.arc.length();
  tc.rotaryStart = canonRotary;
  tc.rotaryEnd = rotaryTo;
  canonEnd = move.end;
  canonRotary = rotaryTo;
  if (tc.target < 1e-12) return;
  // The axes the arc moves: its plane's, and the normal one for a helix.
  const PlaneAxes axes = tc.arc.axes;
  double velocity = std::min(machine.axes[axes.u].maxVelocity, machine.axes[axes.v].maxVelocity);
  double acceleration = std::min(machine.axes[axes.u].maxAcceleration, machine.axes[axes.v].maxAcceleration);
  if (std::abs(tc.arc.endW - tc.arc.startW) > 1e-12) {
    velocity = std::min(velocity, machine.axes[axes.w].maxVelocity);
    acceleration = std::min(acceleration, machine.axes[axes.w].maxAcceleration);
  }
  capByRotary(rotaryAxes, tc.rotaryEnd - tc.rotaryStart, tc.target, velocity, acceleration);
  tc.maxVelocity = velocity;
  tc.requested = move.feed / 60.0;
  tc.maxAcceleration = acceleration;
  tc.part = part;
  enqueue(std::move(tc), move.flags);
}

void LinuxCncMotion::Impl::enqueue(Segment tc, std::uint8_t flags) {
  tc.nominalLength = tc.target;
  tc.maxVelocity = std::min(tc.maxVelocity, tc.target / machine.cycle);
  tc.cycle = machine.cycle;
  tc.tolerance = blending.blend;
  tc.term = !(flags & kExactStop) ? Term::Parabolic : (flags & kExactPath) ? Term::Exact : Term::Stop;
  pathLength += tc.target;
  ++segments;
  joinToPrevious(tc);
  queue.segments.push_back(std::move(tc));
  optimize();
}

// How the new segment meets the one before it (tpFinalizeAndEnqueue, tpHandleBlendArc).
void LinuxCncMotion::Impl::joinToPrevious(Segment& tc) {
  if (queue.segments.empty()) return;
  Segment* prev = &queue.segments.back();
  tc.blendBefore = prev->term == Term::Parabolic;
  if (prev->traverse != tc.traverse) setTerm(prev, &tc, Term::Stop);
  // Where a rotary axis turns on either, LinuxCNC checks no tangency and makes no blend arc
  // (tpSetupTangent fails): the parabolic blend of G64 stays.
  // Nor does it then tell the new segment that it blends with the previous one: only the
  // previous one halves its acceleration.
  const bool rotary = prev->rotates() || tc.rotates();
  if (rotary) tc.blendBefore = false;
  if (!rotary && prev->progress <= prev->target / 2 && setUpTangent(*prev, tc, bounds) == TangentCheck::Kink) {
    std::optional<BlendArc> blend;
    if (prev->term == Term::Parabolic && !prev->finalized)
      blend = prev->shape == Shape::Line && tc.shape == Shape::Line ? lineLineBlend(*prev, tc, bounds)
                                                                      : arcBlend(*prev, tc, bounds);
    if (blend && chooseBestBlend(*prev, tc, &blend->segment) == Joint::Arc) {
      if (insertBlend(prev, tc, *blend)) prev = nullptr;
    } else if (!blend) {
      chooseBestBlend(*prev, tc, nullptr);
    }
  }
  if (prev) finalize(*prev);
}

// Cuts both segments to the blend arc and queues it; true if it took the rest of `prev`.
bool LinuxCncMotion::Impl::insertBlend(Segment* prev, Segment& tc, BlendArc& blend) {
  tc.start = blend.arcEnd;
  if (tc.shape == Shape::Arc) {
    tc.arc = blend.nextArc;
    tc.target = tc.arc.length();
  } else {
    tc.target = (tc.end - tc.start).norm();
  }
  blend.segment.part = tc.part;
  blend.segment.cycle = machine.cycle;
  bool consumed = false;
  if (blend.consumesPrevious && !prev->active) {
    queue.segments.pop_back();
    consumed = true;
    tc.blendBefore = false;
  } else {
    blend.segment.target -= blend.segment.lead;
    blend.segment.nominalLength = blend.segment.target;
    blend.segment.start = blend.arcStart;
    blend.segment.lead = 0;
    blend.segment.maxVelocity = std::min(blend.segment.maxVelocity, blend.segment.target / machine.cycle);
    prev->end = blend.arcStart;
    if (prev->shape == Shape::Arc) {
      prev->arc = blend.prevArc;
      prev->target = prev->arc.length();
    } else {
      prev->target = (prev->end - prev->start).norm();
    }
    setTerm(prev, &tc, Term::Tangent);
  }
  queue.segments.push_back(std::move(blend.segment));
  return consumed;
}

void LinuxCncMotion::Impl::finalize(Segment& s) const {
  if (s.finalized) return;
  s.maxVelocity = std::min(s.maxVelocity, s.target / machine.cycle);
  if (s.shape == Shape::Arc) {
    const bool parabolic = s.blendBefore || s.term == Term::Parabolic;
    const double a = parabolic ? s.maxAcceleration / 2 : s.maxAcceleration;
    s.maxVelocity = std::min(s.maxVelocity, std::sqrt(kNormalShare * a * s.arc.minRadius()));
  }
  s.finalized = true;
}

// The backward pass over the last segments queued (tpRunOptimization).
void LinuxCncMotion::Impl::optimize() {
  std::deque<Segment>& q = queue.segments;
  const int length = static_cast<int>(q.size());
  int peaks = 0;
  bool nonTangent = false;
  for (int x = 1; x < kLookAheadDepth + 2; ++x) {
    const int index = length - x;
    if (index < 1) return;
    Segment& tc = q[static_cast<std::size_t>(index)];
    Segment& prev = q[static_cast<std::size_t>(index - 1)];
    if (prev.term != Term::Tangent) {
      if (nonTangent) return;
      nonTangent = true;
      continue;
    }
    if (prev.progress / prev.target >= 0.25 || prev.splitting || prev.blendingNext) return;
    if (!tc.finalized) {
      // The last segment may still lose half of its length to a blend.
      prev.finalVelocity = std::min(prev.maxVelocity, std::min(peakVelocity(tangentialAcceleration(tc), tc.target),
                                                               maxTargetVelocity(tc)));
      if (prev.kinkVelocity >= 0) prev.finalVelocity = std::min(prev.finalVelocity, prev.kinkVelocity);
      tc.finalVelocity = 0;
    } else {
      double startVelocity = std::sqrt(tc.finalVelocity * tc.finalVelocity + 2.0 * tangentialAcceleration(tc) * tc.target);
      double limit = std::min(tc.maxVelocity, prev.maxVelocity);
      if (prev.kinkVelocity >= 0) limit = std::min(limit, prev.kinkVelocity);
      if (startVelocity >= limit) {
        startVelocity = limit;
        prev.atPeak = true;
      }
      prev.finalVelocity = startVelocity;
      tc.maxVelocity = std::min(tc.maxVelocity, tc.target / (machine.cycle * kMinSegmentCycles));
    }
    if (tc.atPeak && ++peaks > kPeaksBeforeStopping) return;
  }
}

void LinuxCncMotion::Impl::runAhead(std::size_t keep) {
  std::size_t stalled = 0;
  while (queue.segments.size() > keep) {
    const double before = queue.segments.front().progress;
    const std::size_t length = queue.segments.size();
    emit(runCycle(queue));
    // A segment that neither moves nor ends is a fault of this model, never a long run.
    stalled = queue.segments.size() == length && queue.segments.front().progress == before ? stalled + 1 : 0;
    if (stalled > kStalledCycles) {
      const Segment& s = queue.segments.front();
      throw std::logic_error(fmt::format("LinuxCNC motion stalled on line {} (progress {} of {} mm, speed {} mm/s, final {}, "
                                         "max {}, requested {}, acceleration {} tangential {}, term {})",
                                         s.part.line, s.progress, s.target, s.velocity, s.finalVelocity,
                                         s.maxVelocity, s.requested, s.maxAcceleration, tangentialAcceleration(s), int(s.term)));
    }
  }
}

void LinuxCncMotion::Impl::emit(const SegmentPart& part) {
  // The position before the first cycle, as a recording starts.
  if (summary.samples == 0 && batch.empty()) push(startPosition, Vec3::Zero(), part);
  lastPart = part;
  push(queue.position, queue.rotary, part);
}

void LinuxCncMotion::Impl::push(const Vec3& position, const Vec3& rotary, const SegmentPart& part) {
  SimSample s{};
  s.line = part.line;
  s.block = part.block;
  s.x = position.x();
  s.y = position.y();
  s.z = position.z();
  s.feed = part.feed;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!machine.kinematics) {
    s.fbX = servos.empty() ? nan : servos[0].step(s.x);
    s.fbY = servos.empty() ? nan : servos[1].step(s.y);
    s.fbZ = servos.empty() ? nan : servos[2].step(s.z);
  } else {
    // The servos follow the linear joints; the tip they give is the feedback (the rotary
    // joints as commanded: their servos are not modelled).
    const FiveAxisKinematics& k = *machine.kinematics;
    TipPose pose{position, {0, 0}};
    for (int i = 0; i < 3; ++i)
      if (rotaryAxes.kinematicsIndex[static_cast<std::size_t>(i)] >= 0)
        pose.rotary[static_cast<std::size_t>(rotaryAxes.kinematicsIndex[static_cast<std::size_t>(i)])] = rotary[i];
    JointPosition joints{position, pose.rotary};
    if (k.toolCentrePoint) {
      joints = jointsFor(k, pose);
    } else {
      const Vec3 tip = tipOf(k, joints).tip;
      s.x = tip.x();
      s.y = tip.y();
      s.z = tip.z();
    }
    const Vec3 axis = toolAxis(k, pose.rotary);
    JointSample j{rotary.x(), rotary.y(), rotary.z(), {joints.linear.x(), joints.linear.y(), joints.linear.z()},
                  {joints.rotary[0], joints.rotary[1]}, {axis.x(), axis.y(), axis.z()}};
    jointBatch.push_back(j);
    jointLimits->note(j, part.line);
    if (servos.empty()) {
      s.fbX = s.fbY = s.fbZ = nan;
    } else {
      const Vec3 followed(servos[0].step(j.linear[0]), servos[1].step(j.linear[1]), servos[2].step(j.linear[2]));
      const Vec3 tip = tipOf(k, JointPosition{followed, joints.rotary}).tip;
      s.fbX = tip.x();
      s.fbY = tip.y();
      s.fbZ = tip.z();
    }
  }
  batch.push_back(s);
  if (batch.size() >= kBatch) flushBatch();
}

void LinuxCncMotion::Impl::hold(double seconds) {
  const auto cycles = static_cast<std::uint64_t>(std::llround(std::max(0.0, seconds) / machine.cycle));
  for (std::uint64_t i = 0; i < cycles; ++i) emit(lastPart);
}

void LinuxCncMotion::Impl::flushBatch() {
  summary.samples += batch.size();
  if (!jointBatch.empty()) sink.consumeJoints(jointBatch.data(), jointBatch.size());
  jointBatch.clear();
  if (!batch.empty()) sink.consumeBatch(batch);
  batch.clear();
  // Cycle by cycle, a move at a crawl (an acceleration of 1e-12 mm/s^2) would run for years of
  // samples before its planned time were known: the run's bound is checked as it is sampled.
  const double seconds = double(summary.samples) * machine.cycle;
  if (seconds > machine.longestRun) throw runTooLongError(machine, "", lastPart.line, 0);
}

LinuxCncMotion::LinuxCncMotion(const Machine& machine, const Vec3& start, SampleSink& sink)
    : impl_(std::make_unique<Impl>(machine, start, sink)) {}

LinuxCncMotion::~LinuxCncMotion() = default;

void LinuxCncMotion::blendingChanged(const PathBlending& blending) { impl_->pendingBlending.push_back(blending); }

void LinuxCncMotion::add(std::uint64_t index, const Move& move, const Vec3& start) {
  impl_->add(index, move, start, impl_->canonRotary);
}

void LinuxCncMotion::add(std::uint64_t index, const Move& move, const Vec3& start, const Vec3& rotaryEnd) {
  impl_->add(index, move, start, rotaryEnd);
}

InterpolationSummary LinuxCncMotion::finish() {
  impl_->flushChain();
  impl_->runAhead(0);
  impl_->flushBatch();
  InterpolationSummary summary = impl_->summary;
  summary.duration = summary.samples > 0 ? double(summary.samples - 1) * impl_->machine.cycle : 0.0;
  return summary;
}

double LinuxCncMotion::pathLength() const { return impl_->pathLength; }
std::vector<Diagnostic> LinuxCncMotion::jointLimitWarnings(const std::string& source) const {
  return impl_->jointLimits ? impl_->jointLimits->warnings(source) : std::vector<Diagnostic>{};
}
std::size_t LinuxCncMotion::segments() const { return impl_->segments; }
double LinuxCncMotion::plannedSeconds() const {
  return double(impl_->summary.samples + impl_->batch.size()) * impl_->machine.cycle;
}

}  // namespace isurface
