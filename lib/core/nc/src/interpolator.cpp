#include "isurface/nc/interpolator.h"

#include <cstddef>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <memory>
#include <optional>
#include <limits>
#include <vector>

#include "isurface/base/units.h"
#include "isurface/gcode/path_segment.h"
#include "isurface/nc/servo.h"

#include "chord_run.h"
#include "corner_blend.h"

namespace isurface {

std::vector<JointChannel> jointChannels(const FiveAxisKinematics& kinematics) {
  std::vector<JointChannel> channels;
  for (const RotaryAxis& axis : kinematics.rotary) {
    const int i = axis.name - 'A';
    if (i < 0 || i > 2) continue;
    channels.push_back({std::string(1, char('a' + i)), offsetof(JointSample, a) + sizeof(double) * std::size_t(i)});
  }
  const char* linear[] = {"joint_x", "joint_y", "joint_z"};
  for (std::size_t i = 0; i < 3; ++i) channels.push_back({linear[i], offsetof(JointSample, linear) + sizeof(double) * i});
  for (std::size_t k = 0; k < 2; ++k) {
    const char name = static_cast<char>(kinematics.rotary[k].name - 'A' + 'a');
    channels.push_back({std::string("joint_") + name, offsetof(JointSample, rotary) + sizeof(double) * k});
  }
  const char* tool[] = {"tool_i", "tool_j", "tool_k"};
  for (std::size_t i = 0; i < 3; ++i) channels.push_back({tool[i], offsetof(JointSample, toolAxis) + sizeof(double) * i});
  return channels;
}


namespace {

// A moving average over an odd number of samples, started as if the input had always been
// `initial`. Its output lags its input by (taps - 1) / 2 samples.
class MovingAverage3 {
 public:
  MovingAverage3(int taps, const Vec3& initial)
      : ring_(taps, initial), sum_(initial * taps), taps_(taps), inverseTaps_(1.0 / taps) {}

  Vec3 push(const Vec3& value) {
    if (taps_ == 1) return value;
    // At rest the output is the position itself, not a running sum's rounding of it.
    repeats_ = value == last_ ? repeats_ + 1 : 1;
    last_ = value;
    sum_ += value - ring_[next_];
    ring_[next_] = value;
    if (++next_ == ring_.size()) next_ = 0;
    // Re-add the window now and then so rounding in the running sum cannot build up.
    if (++pushesSinceResum_ == (1u << 20)) {
      pushesSinceResum_ = 0;
      sum_.setZero();
      for (const Vec3& v : ring_) sum_ += v;
    }
    // A product, not a quotient: division was a quarter of the interpolator's time per sample
    // (the two differ by an ulp, 1e-14 mm).
    return repeats_ >= taps_ ? value : Vec3(sum_ * inverseTaps_);
  }
  int lag() const { return (taps_ - 1) / 2; }

 private:
  std::vector<Vec3> ring_;
  Vec3 sum_;
  int taps_;
  double inverseTaps_;
  int repeats_ = 0;
  Vec3 last_ = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  std::size_t next_ = 0;
  unsigned pushesSinceResum_ = 0;
};

// A sample is labelled with a neighbouring block only when it is this much nearer to its
// segment (mm): where the path goes straight on, both are as near.
constexpr double kRelabelMargin = 0.0005;
// How far before a junction (mm, along the direction there) a neighbour is still looked at.
constexpr double kJunctionMargin = 0.01;

// A power of two at least n: the ring of tags is indexed by a mask, not a division.
std::size_t ringSize(int n) {
  std::size_t size = 1;
  while (size < static_cast<std::size_t>(n)) size *= 2;
  return size;
}

int taps(double time, double cycle) {
  return time > 0 ? 2 * static_cast<int>(std::lround((time / cycle - 1.0) / 2.0)) + 1 : 1;
}

struct SampleTag {
  std::uint32_t line, block;
  double feedMmMin;           // programmed feed (the rapid rate on a G0), for the `feed` channel
  std::uint32_t segment = 0;  // its geometry's place in the interpolator's ring of segments
};

// A segment the filters' window still reaches, for labelling the samples near its ends.
struct RecentSegment {
  std::uint32_t block;
  PathSegment geometry;
  Vec3 startTangent, endTangent;
};

// A segment of the plan with what walking it needs.
struct QueuedSegment {
  PlannedSegment planned;
  Move move;
  Vec3 start;
};

// Walks the unfiltered profile one cycle at a time, over segments handed to it as they come.
class ProfileWalker {
 public:
  // `rapidFeedMmMin`: the feed channel's value on a rapid.
  ProfileWalker(const Vec3& start, double holdBefore, double rapidFeedMmMin)
      : rapidFeedMmMin_(rapidFeedMmMin), tau_(-holdBefore), last_(start) {}

  void add(const QueuedSegment& segment) {
    queue_.push_back(segment);
    if (!active_ && !ended_) enter();
  }
  bool started() const { return active_ || ended_; }
  bool active() const { return active_; }

  // Catches up with the time advanced: moves on over the segments whose time has run out.
  // False when that needs a segment not handed over yet (and `final` is not set).
  bool settle(bool final) {
    while (active_ && tau_ >= total_) {
      if (queue_.size() < 2 && !final) return false;
      tau_ -= total_;
      last_ = geometry_.end();
      queue_.pop_front();
      if (queue_.empty()) {
        active_ = false;
        ended_ = true;
      } else {
        enter();
      }
    }
    return true;
  }

  // Position at the current time; then `advance(cycle)`.
  Vec3 position() const { return active_ ? geometry_.at(distance()) : last_; }
  // A corner blend's first half belongs to the move before it (it lies nearer that move's line).
  SampleTag tag() const {
    if (inBlend_ && distance() < 0.5 * queue_.front().planned.length) return tagBefore_;
    return currentTag_;
  }
  // The program geometry of the move the tag names.
  const PathSegment& moveGeometry(const SampleTag& tag) const {
    return tag.block == queue_.front().planned.move ? move_ : moveBefore_;
  }
  void advance(double dt) { tau_ += dt; }

 private:
  void enter() {
    const QueuedSegment& q = queue_.front();
    const PlannedSegment& s = q.planned;
    if (s.move != currentMove_) {
      moveBefore_ = move_;
      tagBefore_ = currentTag_;
      move_ = PathSegment::from(q.start, q.move);
      currentMove_ = s.move;
      currentTag_ = tagOf(q, rapidFeedMmMin_);
    }
    const std::optional<CornerBlend> blend =
        s.cornerReach > 0 ? CornerBlend::at(q.start, incoming_, move_.direction, s.cornerReach) : std::nullopt;
    inBlend_ = blend.has_value();
    if (s.smooth)
      geometry_ = PathPiece(curveOf(move_, s.chordCurve));
    else
      geometry_ = blend ? PathPiece(*blend) : PathPiece(shortenedLine(move_, s.trimStart, s.trimEnd));
    incoming_ = geometry_.endTangent();
    tAccel_ = s.accelTime();
    tCruise_ = s.cruiseTime();
    tDecel_ = s.decelTime();
    total_ = tAccel_ + tCruise_ + tDecel_ + s.holdAfter;
    dAccel_ = s.accelDistance();
    last_ = geometry_.end();
    active_ = true;
  }

  double distance() const {
    const PlannedSegment& s = queue_.front().planned;
    double t = tau_;
    if (t <= 0) return 0;
    if (t < tAccel_) return s.entrySpeed * t + 0.5 * s.accel * t * t;
    t -= tAccel_;
    if (t < tCruise_) return dAccel_ + s.peakSpeed * t;
    t -= tCruise_;
    if (t < tDecel_) {
      const double d = dAccel_ + s.peakSpeed * tCruise_ + s.peakSpeed * t - 0.5 * s.accel * t * t;
      return std::min(d, s.length);
    }
    return s.length;
  }

  std::deque<QueuedSegment> queue_;  // the front is the segment being walked
  bool active_ = false, ended_ = false;
  static SampleTag tagOf(const QueuedSegment& q, double rapidFeedMmMin) {
    return SampleTag{q.move.line, q.planned.move,
                     q.move.kind == MoveKind::Rapid ? rapidFeedMmMin : static_cast<double>(q.move.feed)};
  }

  double rapidFeedMmMin_;
  PathPiece geometry_;
  Vec3 incoming_ = Vec3::Zero();  // the direction the last piece ended in
  // The move being walked and the one before it (a blend's first half is labelled with it).
  PathSegment move_, moveBefore_;
  std::uint32_t currentMove_ = ~std::uint32_t{0};
  SampleTag currentTag_{0, 0, 0}, tagBefore_{0, 0, 0};
  bool inBlend_ = false;
  double tau_ = 0, total_ = 0;
  double tAccel_ = 0, tCruise_ = 0, tDecel_ = 0, dAccel_ = 0;
  Vec3 last_;
};

}  // namespace

struct StreamingInterpolator::Impl {
  Impl(const Machine& m, const Vec3& startPosition, double holdBefore, double filterTime1, double filterTime2,
       SampleSink& s)
      : machine(m),
        sink(s),
        feedback(s.wantsFeedback()),
        start(startPosition),
        walker(startPosition, holdBefore, mmPerSToMmPerMin(m.rapidVelocity)),
        holdBefore(holdBefore),
        jerkFilter(taps(filterTime1, m.cycle), startPosition),
        cornerFilter(taps(filterTime2, m.cycle), startPosition),
        delay(jerkFilter.lag() + cornerFilter.lag()),
        tags(ringSize(2 * delay + 1)),
        pendingChanges(tags.size()),
        segments(tags.size()),
        servos{AxisServo(m.axes[0], m.cycle, startPosition[0]), AxisServo(m.axes[1], m.cycle, startPosition[1]),
               AxisServo(m.axes[2], m.cycle, startPosition[2])} {
    batch.reserve(kBatch);
  }

  void emit(const Vec3& commanded, const SampleTag& tag) {
    SimSample s;
    s.line = tag.line;
    s.block = tag.block;
    s.x = commanded[0];
    s.y = commanded[1];
    s.z = commanded[2];
    if (feedback) {
      s.fbX = servos[0].step(commanded[0]);
      s.fbY = servos[1].step(commanded[1]);
      s.fbZ = servos[2].step(commanded[2]);
    } else {
      s.fbX = s.fbY = s.fbZ = std::numeric_limits<double>::quiet_NaN();
    }
    s.feed = tag.feedMmMin;
    batch.push_back(s);
    if (batch.size() == kBatch) flush();
  }
  void flush() {
    if (batch.empty()) return;
    samples += batch.size();
    sink.consumeBatch(batch);  // leaves it empty
    if (batch.capacity() < kBatch) batch.reserve(kBatch);
  }
  void push(const Vec3& raw, const SampleTag& tag) {
    if (rawIndex > 0 && tag.block != tagOf(rawIndex - 1).block) pendingChanges[changesIn++ & ringMask()] = rawIndex;
    tags[rawIndex & ringMask()] = tag;
    const Vec3 smoothed = cornerFilter.push(jerkFilter.push(raw));
    // The filters start moving `delay` cycles before the profile does: those samples belong
    // to the first move too.
    emit(smoothed, rawIndex >= static_cast<std::uint64_t>(delay) ? nearestLabel(smoothed) : tags[0]);
    ++rawIndex;
  }
  // The output stands for the raw profile `delay` cycles back, but averaged over the cycles
  // around it: where a block ends within that window, the sample may lie on the next (or the
  // previous) block's segment. It is labelled with the block whose segment it is nearest to,
  // so that a pick there names the line the tool is on.
  SampleTag nearestLabel(const Vec3& p) {
    const std::uint64_t centre = rawIndex - static_cast<std::uint64_t>(delay);
    // The changes of block at or before the centre have passed it: the last is the one before.
    while (changesOut < changesIn && pendingChanges[changesOut & ringMask()] <= centre)
      lastChange = pendingChanges[changesOut++ & ringMask()];
    const SampleTag& own = tagOf(centre);
    const bool hasNext = changesOut < changesIn;
    // The block before the last change, while its samples are still in the filters' window.
    const bool hasPrevious = lastChange != kNoChange && lastChange + static_cast<std::uint64_t>(delay) > centre;
    if (!hasNext && !hasPrevious) return own;
    SampleTag chosen = own;
    double best = -1;  // the distance to the own segment, once needed
    const auto consider = [&](const SampleTag& other) {
      if (best < 0) best = segmentOf(own).geometry.nearest(p).distance;
      const double d = segmentOf(other).geometry.nearest(p).distance;
      if (d < best - kRelabelMargin) best = d, chosen = other;
    };
    // A neighbour can be nearer only past the junction, along its direction there (with a
    // margin for a curving arc): most samples are decided without a distance.
    if (hasNext) {
      const SampleTag& next = tagOf(pendingChanges[changesOut & ringMask()]);
      const RecentSegment& n = segmentOf(next);
      if ((p - n.geometry.start).dot(n.startTangent) > -kJunctionMargin) consider(next);
    }
    if (hasPrevious) {
      const SampleTag& previous = tagOf(lastChange - 1);
      const RecentSegment& b = segmentOf(previous);
      if ((p - b.geometry.end).dot(b.endTangent) < kJunctionMargin) consider(previous);
    }
    return chosen;
  }
  std::uint64_t ringMask() const { return tags.size() - 1; }
  const SampleTag& tagOf(std::uint64_t raw) const { return tags[raw & ringMask()]; }
  const RecentSegment& segmentOf(const SampleTag& tag) const { return segments[tag.segment & ringMask()]; }

  // Samples every cycle whose position is known.
  void run(bool final) {
    const double cycle = machine.cycle;
    for (;;) {
      if (advanced) {
        if (!walker.settle(final)) return;
        advanced = false;
      }
      if (!walker.active()) return;
      const std::uint32_t previousBlock = lastTag.block;
      lastTag = walker.tag();
      // A ring as long as the tags' holds every segment a tag in the window can name.
      if (rawIndex == 0 || lastTag.block != previousBlock) {
        const PathSegment& g = walker.moveGeometry(lastTag);
        segments[++segmentsIn & ringMask()] = {lastTag.block, g, g.startTangent(), g.endTangent()};
      }
      lastTag.segment = segmentsIn;
      push(walker.position(), lastTag);
      walker.advance(cycle);
      advanced = true;
      if (progress && (rawIndex & 0x3FFFF) == 0) progress(std::min(1.0, rawIndex * cycle / progressTotal));
    }
  }

  static constexpr std::size_t kBatch = 4096;
  const Machine& machine;
  SampleSink& sink;
  const bool feedback;
  const Vec3 start;
  ProfileWalker walker;
  const double holdBefore;
  MovingAverage3 jerkFilter, cornerFilter;
  const int delay;
  // Rings (a power of two, at least 2 delay + 1 long): the tags of the last raw samples, the
  // raw indices where the block changes after the centre of the filters' window, and the
  // segments the tags name.
  std::vector<SampleTag> tags;
  std::vector<std::uint64_t> pendingChanges;
  std::vector<RecentSegment> segments;
  std::uint64_t changesIn = 0, changesOut = 0;
  static constexpr std::uint64_t kNoChange = ~std::uint64_t{0};
  std::uint64_t lastChange = kNoChange;  // the last change at or before the centre
  std::uint32_t segmentsIn = 0;
  std::array<AxisServo, 3> servos;
  std::vector<SimSample> batch;
  std::uint64_t rawIndex = 0, samples = 0;
  SampleTag lastTag{0, 0, 0};
  bool advanced = false;  // time has advanced since the walker last caught up
  ProgressCallback progress;
  double progressTotal = 1;
};

StreamingInterpolator::StreamingInterpolator(const Machine& machine, const Vec3& start, double holdBefore,
                                             double filterTime1, double filterTime2, SampleSink& sink)
    : impl_(std::make_unique<Impl>(machine, start, holdBefore, filterTime1, filterTime2, sink)) {}

StreamingInterpolator::~StreamingInterpolator() = default;

void StreamingInterpolator::reportProgress(ProgressCallback progress, double totalSeconds) {
  impl_->progress = std::move(progress);
  impl_->progressTotal = std::max(totalSeconds, impl_->machine.cycle);
}

void StreamingInterpolator::add(const PlannedSegment& segment, const Move& move, const Vec3& start) {
  impl_->walker.add(QueuedSegment{segment, move, start});
  impl_->run(false);
}

InterpolationSummary StreamingInterpolator::finish() {
  Impl& d = *impl_;
  d.run(true);
  // A program of dwells alone still takes their time.
  if (!d.walker.started())
    for (double t = 0; t < d.holdBefore; t += d.machine.cycle) d.push(d.start, d.lastTag);
  // The final point at rest, until the filters hold nothing else.
  const Vec3 finalPosition = d.walker.position();
  for (int i = 0; i <= 2 * d.delay; ++i) d.push(finalPosition, d.lastTag);
  d.flush();
  InterpolationSummary summary;
  summary.samples = d.samples;
  summary.duration = d.samples > 0 ? (d.samples - 1) * d.machine.cycle : 0;
  if (d.progress) d.progress(1.0);
  return summary;
}

InterpolationSummary interpolate(const Program& program, const Machine& machine, const FeedPlan& plan,
                                 SampleSink& sink, const ProgressCallback& progress) {
  StreamingInterpolator interpolator(machine, program.start, plan.holdBefore, plan.filterTime1, plan.filterTime2,
                                     sink);
  if (progress) interpolator.reportProgress(progress, plan.profileDuration());
  for (const PlannedSegment& segment : plan.segments)
    interpolator.add(segment, program.moves[segment.move], program.startOf(segment.move));
  return interpolator.finish();
}

}  // namespace isurface
