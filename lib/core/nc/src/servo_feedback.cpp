// Replaying the servo over a run's commanded samples.
#include "isurface/nc/servo_feedback.h"

#include <algorithm>
#include <array>

#include "isurface/base/available_memory.h"
#include "isurface/nc/servo.h"

namespace isurface {

FeedbackOffsets servoFeedback(const Trajectory& commanded, const Machine& machine, const Vec3& start,
                              const ProgressCallback& progress) {
  const std::size_t n = commanded.size();
  requireMemory(commanded.source, "the servo's positions of " + std::to_string(n) + " samples", std::uint64_t(n) * 12,
                availableMemory());
  FeedbackOffsets out;
  if (n == 0) return out;
  const std::array<const std::vector<double>*, 3> axes = {&commanded.x, &commanded.y, &commanded.z};
  const std::array<std::vector<float>*, 3> offsets = {&out.x, &out.y, &out.z};
  // One axis at a time, in steps, so that progress (and a cancellation) comes between them.
  constexpr std::size_t kStep = std::size_t(1) << 20;
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<double>& position = *axes[axis];
    std::vector<float>& offset = *offsets[axis];
    offset.resize(n);
    AxisServo servo(machine.axes[static_cast<std::size_t>(axis)], machine.cycle, start[axis]);
    for (std::size_t begin = 0; begin < n; begin += kStep) {
      const std::size_t end = std::min(n, begin + kStep);
      for (std::size_t i = begin; i < end; ++i) offset[i] = static_cast<float>(servo.step(position[i]) - position[i]);
      if (progress) progress((double(axis) + double(end) / double(n)) / 3.0);
    }
  }
  return out;
}

}  // namespace isurface
