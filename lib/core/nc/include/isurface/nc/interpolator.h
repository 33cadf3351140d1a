#pragma once
// The NC interpolator: samples a feed plan at the machine's cycle along the exact geometry,
// smooths the axis commands with the plan's filters and runs each axis through its servo.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "isurface/nc/feed_plan.h"

namespace isurface {

// One interpolation cycle. Laid out like a Biip record with channels line, block, x y z,
// fb_x fb_y fb_z and feed, so that it can be written as it is.
struct SimSample {
  std::uint32_t line;   // 1-based source line, 0 outside the program
  std::uint32_t block;  // index of the move in Program::moves
  double x, y, z;       // commanded position, mm
  double fbX, fbY, fbZ; // encoder feedback position, mm
  double feed;          // programmed feed in effect, mm/min
};
static_assert(sizeof(SimSample) == 64, "SimSample must match the Biip record layout");

// The same cycle's rotary axes and joints, on a machine with rotary axes (its SimSample then
// holds the tool tip in the workpiece frame).
struct JointSample {
  double a, b, c;          // deg, the program's rotary axes
  double linear[3];        // mm, the machine's X Y Z joints
  double rotary[2];        // deg, its rotary joints in FiveAxisKinematics::rotary order
  double toolAxis[3];      // unit, the tool's direction (tip towards spindle) in the workpiece frame
};

// The channels a five-axis run adds to its samples: the machine's rotary axes ("b", "c"), its
// joints ("joint_x", "joint_y", "joint_z", "joint_b", "joint_c") and the tool axis in the
// workpiece frame ("tool_i", "tool_j", "tool_k"), each read from a JointSample.
struct JointChannel {
  std::string name;
  std::size_t offset;  // bytes into a JointSample of its double
  double of(const JointSample& j) const {
    return *reinterpret_cast<const double*>(reinterpret_cast<const char*>(&j) + offset);
  }
};
std::vector<JointChannel> jointChannels(const FiveAxisKinematics& kinematics);

class SampleSink {
 public:
  virtual ~SampleSink() = default;
  // About how many samples are coming (a hint, given once the plan is known: room can be made
  // for them at once instead of growing as they come).
  virtual void expect(std::size_t /*samples*/) {}
  // False when the sink drops the servo's positions: the servo is then not simulated (fbX, fbY
  // and fbZ of its samples are NaN).
  virtual bool wantsFeedback() const { return true; }
  virtual void consume(const SimSample* samples, std::size_t count) = 0;
  // On a machine with rotary axes, the joints of the samples of the consume() call that follows,
  // one for each. A sink that cannot keep them says so: a five-axis run is never cut to its tip.
  virtual bool keepsJoints() const { return false; }
  virtual void consumeJoints(const JointSample* /*joints*/, std::size_t /*count*/) {}
  // A whole batch handed over with its buffer: a sink that keeps batches for later (ThreadedSink)
  // takes the vector and leaves an empty one in its place instead of copying 64 bytes a sample.
  // `batch` is empty on return.
  virtual void consumeBatch(std::vector<SimSample>& batch) {
    consume(batch.data(), batch.size());
    batch.clear();
  }
};

struct InterpolationSummary {
  std::uint64_t samples = 0;
  double duration = 0;  // s, from the first sample to the last
};

InterpolationSummary interpolate(const Program& program, const Machine& machine, const FeedPlan& plan,
                                 SampleSink& sink, const ProgressCallback& progress = {});

// The interpolator fed one planned segment at a time (interpolate() is this over a whole plan):
// each add() samples every cycle that no later segment can change, so that it holds only the
// segment being walked and the filters' few cycles. The machine and the sink must outlive it.
class StreamingInterpolator {
 public:
  // `start`: the position before the first move, mm; `holdBefore`: s of dwell before the first
  // motion; the filter times are the plan's.
  StreamingInterpolator(const Machine& machine, const Vec3& start, double holdBefore, double filterTime1,
                        double filterTime2, SampleSink& sink);
  ~StreamingInterpolator();
  StreamingInterpolator(const StreamingInterpolator&) = delete;
  StreamingInterpolator& operator=(const StreamingInterpolator&) = delete;

  // Reports the fraction of `totalSeconds` of profile sampled so far.
  void reportProgress(ProgressCallback progress, double totalSeconds);
  // The next segment of the plan and its move, which starts at `start`.
  void add(const PlannedSegment& segment, const Move& move, const Vec3& start);
  // No more segments: samples the rest, then the standstill until the filters have settled.
  InterpolationSummary finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace isurface
