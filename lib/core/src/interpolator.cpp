#include "isurface/core/interpolator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "isurface/core/path_segment.h"
#include "isurface/core/servo.h"

namespace isurface {

namespace {

// A moving average over an odd number of samples, started as if the input had always been
// `initial`. Its output lags its input by (taps - 1) / 2 samples.
class MovingAverage3 {
 public:
  MovingAverage3(int taps, const Vec3& initial) : ring_(taps, initial), sum_(initial * taps), taps_(taps) {}

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
    return repeats_ >= taps_ ? value : Vec3(sum_ / taps_);
  }
  int lag() const { return (taps_ - 1) / 2; }

 private:
  std::vector<Vec3> ring_;
  Vec3 sum_;
  int taps_;
  int repeats_ = 0;
  Vec3 last_ = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  std::size_t next_ = 0;
  unsigned pushesSinceResum_ = 0;
};

int taps(double time, double cycle) {
  return time > 0 ? 2 * static_cast<int>(std::lround((time / cycle - 1.0) / 2.0)) + 1 : 1;
}

// Walks the unfiltered profile one cycle at a time.
class ProfileWalker {
 public:
  ProfileWalker(const Program& program, const FeedPlan& plan)
      : program_(program), plan_(plan), last_(program.start) {
    tau_ = -plan.holdBefore;
    if (!plan.segments.empty()) enter(0);
  }

  bool done() const { return index_ >= plan_.segments.size(); }
  std::size_t index() const { return index_; }

  // Position at the current time; then `advance(cycle)`.
  Vec3 position() const {
    if (done()) return last_;
    return geometry_.at(distance());
  }
  const PlannedSegment& segment() const { return plan_.segments[index_]; }

  void advance(double dt) {
    tau_ += dt;
    while (!done() && tau_ >= total_) {
      tau_ -= total_;
      last_ = geometry_.end;
      if (++index_ < plan_.segments.size()) enter(index_);
    }
  }

 private:
  void enter(std::size_t k) {
    index_ = k;
    const PlannedSegment& s = plan_.segments[k];
    geometry_ = PathSegment::from(program_, s.move);
    tAccel_ = s.accelTime();
    tCruise_ = s.cruiseTime();
    tDecel_ = s.decelTime();
    total_ = tAccel_ + tCruise_ + tDecel_ + s.holdAfter;
    dAccel_ = s.accelDistance();
    last_ = geometry_.end;
  }

  double distance() const {
    const PlannedSegment& s = plan_.segments[index_];
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

  const Program& program_;
  const FeedPlan& plan_;
  std::size_t index_ = 0;
  PathSegment geometry_;
  double tau_ = 0, total_ = 0;
  double tAccel_ = 0, tCruise_ = 0, tDecel_ = 0, dAccel_ = 0;
  Vec3 last_;
};

struct SampleTag {
  std::uint32_t line, block;
  double feed;
};

}  // namespace

InterpolationSummary interpolate(const Program& program, const Machine& machine, const FeedPlan& plan,
                                 SampleSink& sink, const ProgressCallback& progress) {
  InterpolationSummary summary;
  const double cycle = machine.cycle;
  ProfileWalker walker(program, plan);
  const Vec3 start = program.start;
  MovingAverage3 jerkFilter(taps(plan.filterTime1, cycle), start);
  MovingAverage3 cornerFilter(taps(plan.filterTime2, cycle), start);
  const int delay = jerkFilter.lag() + cornerFilter.lag();
  std::vector<SampleTag> tags(delay + 1);
  std::array<AxisServo, 3> servos{AxisServo(machine.axes[0], cycle, start[0]),
                                  AxisServo(machine.axes[1], cycle, start[1]),
                                  AxisServo(machine.axes[2], cycle, start[2])};

  std::vector<SimSample> batch;
  constexpr std::size_t kBatch = 4096;
  batch.reserve(kBatch);
  const double totalTime = std::max(plan.profileDuration(), cycle);
  std::uint64_t rawIndex = 0;
  SampleTag lastTag{0, 0, 0};

  auto emit = [&](const Vec3& commanded, const SampleTag& tag) {
    SimSample s;
    s.line = tag.line;
    s.block = tag.block;
    s.x = commanded[0];
    s.y = commanded[1];
    s.z = commanded[2];
    s.fbX = servos[0].step(commanded[0]);
    s.fbY = servos[1].step(commanded[1]);
    s.fbZ = servos[2].step(commanded[2]);
    s.feed = tag.feed;
    batch.push_back(s);
    if (batch.size() == kBatch) {
      sink.consume(batch.data(), batch.size());
      summary.samples += batch.size();
      batch.clear();
    }
  };
  auto push = [&](const Vec3& raw, const SampleTag& tag) {
    const std::size_t slot = rawIndex % tags.size();
    tags[slot] = tag;
    const Vec3 smoothed = cornerFilter.push(jerkFilter.push(raw));
    // The filters start moving `delay` cycles before the profile does: those samples belong
    // to the first move too.
    emit(smoothed, rawIndex >= static_cast<std::uint64_t>(delay) ? tags[(rawIndex + 1) % tags.size()] : tags[0]);
    ++rawIndex;
  };

  while (!walker.done()) {
    const PlannedSegment& seg = walker.segment();
    const Move& move = program.moves[seg.move];
    lastTag = SampleTag{move.line, seg.move,
                        move.kind == MoveKind::Rapid ? machine.rapidVelocity * 60.0 : static_cast<double>(move.feed)};
    push(walker.position(), lastTag);
    walker.advance(cycle);
    if (progress && (rawIndex & 0x3FFFF) == 0) progress(std::min(1.0, rawIndex * cycle / totalTime));
  }
  // A program of dwells alone still takes their time.
  if (plan.segments.empty())
    for (double t = 0; t < plan.holdBefore; t += cycle) push(start, lastTag);
  // The final point at rest, until the filters hold nothing else.
  const Vec3 finalPosition = walker.position();
  for (int i = 0; i <= 2 * delay; ++i) push(finalPosition, lastTag);
  if (!batch.empty()) {
    sink.consume(batch.data(), batch.size());
    summary.samples += batch.size();
  }
  summary.duration = summary.samples > 0 ? (summary.samples - 1) * cycle : 0;
  if (progress) progress(1.0);
  return summary;
}

}  // namespace isurface
