#pragma once
// The simulator's samples as a Trajectory, for analysis in memory.
#include <string>
#include <vector>

#include "isurface/base/trajectory.h"
#include "isurface/nc/interpolator.h"

namespace isurface {

// Samples written straight into a Trajectory's channels as the simulator makes them: no
// buffer of records beside it, which for a long program is as large as the Trajectory itself.
// rapidFeed is left 0: set it from the machine when the caller knows it. Without `feedback`
// the servo's positions are not kept (24 bytes a sample less, for what shows no feedback).
class TrajectorySink : public SampleSink {
 public:
  TrajectorySink(double cycle, std::string source, bool feedback = true);
  void expect(std::size_t samples) override;
  void consume(const SimSample* samples, std::size_t count) override;
  bool wantsFeedback() const override { return feedback_; }
  // Keeps a five-axis run's rotary axes and joints as extra channels (jointChannels).
  void keepJointsOf(const FiveAxisKinematics& kinematics);
  bool keepsJoints() const override { return !jointChannels_.empty(); }
  void consumeJoints(const JointSample* joints, std::size_t count) override;
  Trajectory take();

 private:
  Trajectory trajectory_;
  bool feedback_;
  std::vector<JointChannel> jointChannels_;
};

Trajectory trajectoryFromSamples(const std::vector<SimSample>& samples, double cycle, const std::string& source);

}  // namespace isurface
