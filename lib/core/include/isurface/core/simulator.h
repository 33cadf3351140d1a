#pragma once
// G-code program + machine -> interpolation samples: feed planning, interpolation and servo.
#include <cstdint>
#include <string>
#include <vector>

#include "isurface/core/biip.h"
#include "isurface/core/interpolator.h"

namespace isurface {

struct SimulationReport {
  std::uint64_t samples = 0;
  double machiningTime = 0;  // s, first to last sample
  double pathLength = 0;     // mm, programmed
  std::size_t segments = 0;  // moves with motion
  double filterTime1 = 0;    // s
  double filterTime2 = 0;    // s
};

// Progress is reported as planning (0..0.1) then interpolation (0.1..1).
SimulationReport simulate(const Program& program, const Machine& machine, SampleSink& sink,
                          const ProgressCallback& progress = {});

// The channel table of a simulated dump: line, block, x y z, fb_x fb_y fb_z, feed.
std::vector<BiipChannel> simulationChannels();

// Simulates into a Biip file written atomically (nothing is left at `path` on failure).
SimulationReport simulateToBiip(const Program& program, const Machine& machine, const std::string& path,
                                const ProgressCallback& progress = {});

// A sink that keeps every sample in memory (tests, small programs).
class SampleBuffer : public SampleSink {
 public:
  void consume(const SimSample* samples, std::size_t count) override {
    data.insert(data.end(), samples, samples + count);
  }
  std::vector<SimSample> data;
};

}  // namespace isurface
