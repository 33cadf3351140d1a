// Fuzz target: the machine description reader on any text (JSON syntax, types, ranges), and a
// short simulation with every description it accepts: a value the reader lets through must
// not make the planner divide by zero, produce NaN or run for ever (libFuzzer's -timeout and
// -rss_limit_mb catch the last).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_support.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/machine/machine.h"
#include "isurface/nc/simulator.h"

namespace {

// Lines, a corner, an arc, a rapid and a dwell: every kind of move the planner treats apart.
const isurface::Program& shortProgram() {
  static const isurface::Program program =
      isurface::interpretGcode("G21 G90 G17\nG0 X0 Y0 Z1\nG1 Z0 F3000\nG1 X2\nG1 Y1\nG2 X1 Y2 R1\nG4 P0.01\nG0 Z2\n",
                               "short.nc")
          .program;
  return program;
}

class FiniteSampleCheck : public isurface::SampleSink {
 public:
  void consume(const isurface::SimSample* samples, std::size_t count) override {
    for (std::size_t i = 0; i < count; ++i) {
      const isurface::SimSample& s = samples[i];
      if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z) || !std::isfinite(s.fbX) ||
          !std::isfinite(s.fbY) || !std::isfinite(s.fbZ))
        std::abort();  // a finding: an accepted machine made a non-finite sample
    }
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  isurface::fuzz::expectOnlyInputErrors([&] {
    const isurface::Machine machine = isurface::parseMachine(text, "fuzz.json");
    FiniteSampleCheck sink;
    isurface::simulate(shortProgram(), machine, sink);
  });
  return 0;
}
