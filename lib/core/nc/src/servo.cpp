#include "isurface/nc/servo.h"

namespace isurface {

AxisServo::AxisServo(const AxisLimits& axis, double cycle, double initialPosition)
    : gain_(axis.positionGain),
      feedForward_(axis.velocityFeedForward),
      // Backward Euler keeps the lag stable for any time constant, even one below the cycle.
      lagFactor_(cycle / (axis.velocityLoopTimeConstant + cycle)),
      cycle_(cycle),
      position_(initialPosition),
      previousCommand_(initialPosition) {}

double AxisServo::step(double commanded) {
  // The encoder is read when the command is issued: what the previous cycles achieved.
  const double measured = position_;
  const double feedForwardVelocity = (commanded - previousCommand_) / cycle_;
  previousCommand_ = commanded;
  const double velocityCommand = feedForward_ * feedForwardVelocity + gain_ * (commanded - position_);
  velocity_ += (velocityCommand - velocity_) * lagFactor_;
  position_ += velocity_ * cycle_;
  return measured;
}

}  // namespace isurface
