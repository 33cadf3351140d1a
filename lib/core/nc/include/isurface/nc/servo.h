#pragma once
// A per-axis servo: proportional position loop with velocity feed-forward around a velocity
// loop modelled as a first-order lag. Turns commanded positions into encoder feedback.
#include "isurface/machine/machine.h"

namespace isurface {

class AxisServo {
 public:
  AxisServo(const AxisLimits& axis, double cycle, double initialPosition);
  // Issues one cycle's commanded position (mm); returns the encoder position read at that
  // instant (mm), then moves for one cycle.
  double step(double commanded);
  double position() const { return position_; }

 private:
  double gain_, feedForward_, lagFactor_, cycle_;  // 1/s, 0..1, 0..1 (share per cycle), s
  double position_, velocity_ = 0, previousCommand_;  // mm, mm/s, mm
};

}  // namespace isurface
