#pragma once
// The NC interpolator: samples a feed plan at the machine's cycle along the exact geometry,
// smooths the axis commands with the plan's filters and runs each axis through its servo.
#include <cstddef>
#include <cstdint>

#include "isurface/core/feed_plan.h"

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

class SampleSink {
 public:
  virtual ~SampleSink() = default;
  virtual void consume(const SimSample* samples, std::size_t count) = 0;
};

struct InterpolationSummary {
  std::uint64_t samples = 0;
  double duration = 0;  // s, from the first sample to the last
};

InterpolationSummary interpolate(const Program& program, const Machine& machine, const FeedPlan& plan,
                                 SampleSink& sink, const ProgressCallback& progress = {});

}  // namespace isurface
