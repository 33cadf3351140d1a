// Simulated samples as a Trajectory.
#include "isurface/nc/sample_trajectory.h"

#include <utility>

namespace isurface {

TrajectorySink::TrajectorySink(double cycle, std::string source, bool feedback) : feedback_(feedback) {
  trajectory_.source = std::move(source);
  trajectory_.cycle = cycle;
  trajectory_.hasLine = true;
}

void TrajectorySink::expect(std::size_t samples) {
  Trajectory& t = trajectory_;
  for (std::vector<double>* channel : {&t.x, &t.y, &t.z}) channel->reserve(samples);
  if (feedback_)
    for (std::vector<float>* channel : {&t.fbOffsetX, &t.fbOffsetY, &t.fbOffsetZ}) channel->reserve(samples);
}

void TrajectorySink::consume(const SimSample* samples, std::size_t count) {
  Trajectory& t = trajectory_;
  for (std::size_t k = 0; k < count; ++k) {
    const SimSample& s = samples[k];
    t.line.push_back(s.line);
    t.block.push_back(s.block);
    t.x.push_back(s.x);
    t.y.push_back(s.y);
    t.z.push_back(s.z);
    t.feed.push_back(static_cast<float>(s.feed));
  }
  if (!feedback_) return;
  for (std::size_t k = 0; k < count; ++k) {
    const SimSample& s = samples[k];
    t.fbOffsetX.push_back(static_cast<float>(s.fbX - s.x));
    t.fbOffsetY.push_back(static_cast<float>(s.fbY - s.y));
    t.fbOffsetZ.push_back(static_cast<float>(s.fbZ - s.z));
  }
}

void TrajectorySink::keepJointsOf(const FiveAxisKinematics& kinematics) {
  jointChannels_ = jointChannels(kinematics);
  for (const JointChannel& c : jointChannels_) trajectory_.extra.emplace_back(c.name, std::vector<double>{});
}

void TrajectorySink::consumeJoints(const JointSample* joints, std::size_t count) {
  // The joint channels are the last extra ones, in jointChannels_ order.
  const std::size_t first = trajectory_.extra.size() - jointChannels_.size();
  for (std::size_t c = 0; c < jointChannels_.size(); ++c) {
    std::vector<double>& values = trajectory_.extra[first + c].second;
    for (std::size_t k = 0; k < count; ++k) values.push_back(jointChannels_[c].of(joints[k]));
  }
}

Trajectory TrajectorySink::take() {
  // The run channels grew by doubling: up to half of each is spare room.
  trajectory_.shrinkRunChannels();
  return std::move(trajectory_);
}

Trajectory trajectoryFromSamples(const std::vector<SimSample>& samples, double cycle, const std::string& source) {
  TrajectorySink sink(cycle, source);
  sink.expect(samples.size());
  sink.consume(samples.data(), samples.size());
  return sink.take();
}

}  // namespace isurface
